#include "preprocessing/derivative.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "core/error.h"
#include "core/parse_number.h"
#include "preprocessing/savitzky_golay.h"
#include "preprocessing/smoothing_spline.h"
#include "preprocessing/tv_derivative.h"

namespace usvid {
namespace {

std::vector<std::string> Split(const std::string& s, char sep) {
  std::vector<std::string> parts;
  std::stringstream in(s);
  for (std::string part; std::getline(in, part, sep);) parts.push_back(part);
  return parts;
}

double Number(const std::string& text, const std::string& spec) {
  const ParsedNumber p = ParseNumber(text);
  if (p.status != NumberStatus::kOk)
    throw InputError("--derivative '" + spec + "': " + DescribeNumberStatus(p.status, text));
  return p.value;
}

// Savitzky-Golay within each stretch between breaks: windows never cross a break (shifted
// inwards at a stretch's ends; a stretch shorter than the window is fitted whole, with the
// order lowered to fit it).
SmoothedSignal SavitzkyGolayPieces(const Eigen::VectorXd& y, double dt, int window, int order,
                                   const std::vector<Eigen::Index>& breaks) {
  std::vector<Eigen::Index> cuts = {0};
  for (Eigen::Index b : breaks)
    if (b > cuts.back() && b < y.size()) cuts.push_back(b);
  cuts.push_back(y.size());
  SmoothedSignal out{Eigen::VectorXd(y.size()), Eigen::VectorXd(y.size())};
  for (size_t k = 0; k + 1 < cuts.size(); ++k) {
    const Eigen::Index a = cuts[k], n = cuts[k + 1] - cuts[k];
    if (n == 1) {
      out.value(a) = y(a);
      out.derivative(a) = NAN;  // filled from the neighbours below
      continue;
    }
    const int w = static_cast<int>(std::min<Eigen::Index>(window, n % 2 == 1 ? n : n - 1));
    const SavitzkyGolay sg{std::max(w, 2), std::min(order, std::max(1, w - 2))};
    for (Eigen::Index i = 0; i < n; ++i) {
      const Eigen::Index start = std::clamp<Eigen::Index>(i - sg.window / 2, 0, n - sg.window);
      const Eigen::VectorXd seg = y.segment(a + start, sg.window);
      const int position = static_cast<int>(i - start);
      out.value(a + i) = sg.Weights(position, 0, dt).dot(seg);
      out.derivative(a + i) = sg.Weights(position, 1, dt).dot(seg);
    }
  }
  for (Eigen::Index i = 0; i < y.size(); ++i)
    if (std::isnan(out.derivative(i)))
      out.derivative(i) = i + 1 < y.size() ? (y(i + 1) - y(i)) / dt : (y(i) - y(i - 1)) / dt;
  return out;
}

}  // namespace

DerivativeMethod DerivativeMethod::Parse(const std::string& spec) {
  const std::vector<std::string> parts = Split(spec, ':');
  const std::string name = parts.empty() ? "" : parts[0];
  DerivativeMethod m;
  auto integer = [&](size_t i) {
    const double v = Number(parts[i], spec);
    if (v != static_cast<int>(v) || v < 1)
      throw InputError("--derivative '" + spec + "': '" + parts[i] + "' is not a positive integer");
    return static_cast<int>(v);
  };
  if (name == "euler") {
    m.kind = Kind::kEuler;
    m.window = parts.size() > 1 ? integer(1) : 11;
    m.order = 2;
  } else if (name == "sg") {
    m.kind = Kind::kSavitzkyGolay;
    if (parts.size() > 1) m.window = integer(1);
    if (parts.size() > 2) m.order = integer(2);
  } else if (name == "spline" || name == "tv") {
    m.kind = name == "tv" ? Kind::kTv : Kind::kSpline;
    if (parts.size() > 1) m.parameter = Number(parts[1], spec);
    if (parts.size() > 1 && !(m.parameter > 0))
      throw InputError("--derivative '" + spec + "': the parameter must be positive");
  } else {
    throw InputError("--derivative '" + spec +
                     "': unknown method (known: sg[:W[:P]], spline[:L], "
                     "tv[:A], euler[:W])");
  }
  if (parts.size() > 3 || (m.kind != Kind::kSavitzkyGolay && parts.size() > 2))
    throw InputError("--derivative '" + spec + "': too many ':' fields");
  if ((m.kind == Kind::kSavitzkyGolay || m.kind == Kind::kEuler) &&
      (m.window % 2 == 0 || m.window < m.order + 2))
    throw InputError("--derivative '" + spec + "': the window must be odd and at least order + 2");
  return m;
}

std::string DerivativeMethod::Spec() const {
  std::ostringstream s;
  switch (kind) {
    case Kind::kEuler:
      s << "euler:" << window;
      break;
    case Kind::kSavitzkyGolay:
      s << "sg:" << window << ":" << order;
      break;
    case Kind::kSpline:
      s << "spline";
      if (parameter > 0) s << ":" << parameter;
      break;
    case Kind::kTv:
      s << "tv";
      if (parameter > 0) s << ":" << parameter;
      break;
  }
  return s.str();
}

std::vector<Eigen::Index> StepBreaks(const std::vector<Eigen::VectorXd>& inputs, double fraction) {
  std::vector<Eigen::Index> breaks;
  if (inputs.empty()) return breaks;
  // An input whose range is within rounding of its size is constant: a held propeller's 91.7
  // rpm comes out of resampling as 91.7 +- 1e-14, and a fraction of that range would make every
  // rounding a step.
  constexpr double kConstant = 1e-9;
  std::vector<double> threshold;
  for (const Eigen::VectorXd& u : inputs) {
    const double range = u.size() ? u.maxCoeff() - u.minCoeff() : 0.0;
    const double size = u.size() ? u.cwiseAbs().maxCoeff() : 0.0;
    threshold.push_back(range > kConstant * size ? fraction * range : 0.0);
  }
  // A step is a change over one sample, between samples that do not change so: where the
  // input moves over several samples in a row it ramps (a rudder or nozzle at its slew rate),
  // and the state's derivative, which integrates it, does not jump.
  const Eigen::Index n = inputs[0].size();
  const auto moves = [&](size_t i, Eigen::Index k) {
    return k >= 1 && k < n && threshold[i] > 0 &&
           std::abs(inputs[i](k) - inputs[i](k - 1)) > threshold[i];
  };
  for (Eigen::Index k = 1; k < n; ++k)
    for (size_t i = 0; i < inputs.size(); ++i)
      if (moves(i, k) && !moves(i, k - 1) && !moves(i, k + 1)) {
        breaks.push_back(k);
        break;
      }
  return breaks;
}

SmoothedSignal SmoothAndDifferentiate(const Eigen::VectorXd& y, double dt,
                                      const DerivativeMethod& method,
                                      const std::vector<Eigen::Index>& breaks) {
  switch (method.kind) {
    case DerivativeMethod::Kind::kEuler: {
      const SavitzkyGolay sg{method.window, 2};
      SmoothedSignal out{sg.Apply(y, dt, 0), Eigen::VectorXd(y.size())};
      // Eq. 4.9 of the report: x'_k = (x_{k+1} - x_k) / (t_{k+1} - t_k), forward differences.
      const Eigen::Index n = y.size();
      for (Eigen::Index i = 0; i + 1 < n; ++i)
        out.derivative(i) = (out.value(i + 1) - out.value(i)) / dt;
      out.derivative(n - 1) = n > 1 ? out.derivative(n - 2) : 0.0;
      return out;
    }
    case DerivativeMethod::Kind::kSavitzkyGolay: {
      if (!breaks.empty()) return SavitzkyGolayPieces(y, dt, method.window, method.order, breaks);
      const SavitzkyGolay sg{method.window, method.order};
      return {sg.Apply(y, dt, 0), sg.Apply(y, dt, 1)};
    }
    case DerivativeMethod::Kind::kSpline: {
      SmoothingSplineResult r = breaks.empty()
                                    ? SmoothingSpline(y, dt, method.parameter)
                                    : PiecewiseSmoothingSpline(y, dt, breaks, method.parameter);
      return {std::move(r.value), std::move(r.derivative)};
    }
    case DerivativeMethod::Kind::kTv: {
      TvDerivativeOptions options;
      options.alpha = method.parameter;
      TvDerivativeResult r = TvDerivative(y, dt, options);
      return {std::move(r.value), std::move(r.derivative)};
    }
  }
  return {};
}

}  // namespace usvid
