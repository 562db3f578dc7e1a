#include "methods/eb_lr/steady_windows.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/dataset.h"
#include "core/error.h"
#include "core/parse_number.h"
#include "preprocessing/derivative.h"
#include "preprocessing/smoothing_spline.h"

namespace usvid::eb_lr {
namespace {

void CheckOptions(const SteadyWindowOptions& o) {
  const std::pair<double, const char*> positive[] = {{o.input_tolerance, "input_tolerance"},
                                                     {o.slope_window_s, "slope_window_s"},
                                                     {o.min_window_s, "min_window_s"}};
  for (const auto& [v, name] : positive)
    if (!(v > 0.0 && std::isfinite(v)))
      throw InputError(std::string("eb-lr option ") + name + ": must be positive and finite, got " +
                       FormatNumber(v));
  const std::pair<double, const char*> non_negative[] = {{o.noise_factor, "noise_factor"},
                                                         {o.max_relative_rate, "max_relative_rate"},
                                                         {o.scale_floor, "scale_floor"}};
  for (const auto& [v, name] : non_negative)
    if (!(v >= 0.0 && std::isfinite(v)))
      throw InputError(std::string("eb-lr option ") + name + ": must be >= 0 and finite, got " +
                       FormatNumber(v));
}

// Marks in `settled` the samples of [a, b] whose local slope of y passes the test.
void MarkSettled(const Eigen::VectorXd& t, const Eigen::VectorXd& y, Eigen::Index a, Eigen::Index b,
                 Eigen::Index half, double sd, double floor, const SteadyWindowOptions& o,
                 std::vector<bool>& settled) {
  for (Eigen::Index k = a; k <= b; ++k) {
    const Eigen::Index lo = std::max(a, k - half), hi = std::min(b, k + half), n = hi - lo + 1;
    const double tm = t.segment(lo, n).mean(), ym = y.segment(lo, n).mean();
    double stt = 0.0, sty = 0.0;
    for (Eigen::Index i = lo; i <= hi; ++i) {
      stt += (t(i) - tm) * (t(i) - tm);
      sty += (t(i) - tm) * (y(i) - ym);
    }
    const double limit =
        o.noise_factor * sd / std::sqrt(stt) + o.max_relative_rate * (std::abs(y(k)) + floor);
    settled[k] = settled[k] && std::abs(sty / stt) <= limit;
  }
}

// Whether no input spreads over [first, last] by more than input_tolerance x its range.
bool InputsHeld(const std::vector<Eigen::VectorXd>& inputs, Eigen::Index first, Eigen::Index last,
                double tolerance) {
  for (const Eigen::VectorXd& u : inputs) {
    const Eigen::VectorXd w = u.segment(first, last - first + 1);
    if (w.maxCoeff() - w.minCoeff() > tolerance * (u.maxCoeff() - u.minCoeff())) return false;
  }
  return true;
}

// The stretch [a, b]'s last full turn of `rate`, if the stretch holds 1.25 turns: its first
// sample, else -1.
Eigen::Index LastFullTurn(const Eigen::VectorXd& t, const Eigen::VectorXd& rate, Eigen::Index a,
                          Eigen::Index b) {
  constexpr double kTurn = 2.0 * 3.141592653589793;
  double heading = 0.0;
  for (Eigen::Index k = b; k > a; --k) {
    heading += 0.5 * (rate(k) + rate(k - 1)) * (t(k) - t(k - 1));
    if (std::abs(heading) >= kTurn) return t(b) - t(k - 1) <= 0.8 * (t(b) - t(a)) ? k - 1 : -1;
  }
  return -1;
}

}  // namespace

SteadyWindowReport DetectSteadyWindows(const Eigen::VectorXd& t,
                                       const std::vector<Eigen::VectorXd>& states,
                                       const std::vector<Eigen::VectorXd>& inputs,
                                       const SteadyWindowOptions& options,
                                       const std::vector<Eigen::Index>& joins) {
  CheckOptions(options);
  const Eigen::Index n = t.size();
  for (const auto* list : {&states, &inputs})
    for (const Eigen::VectorXd& v : *list)
      if (v.size() != n) throw InputError("eb-lr: a state or input is not as long as t");
  SteadyWindowReport report;
  if (n < 2) return report;
  std::vector<Eigen::Index> cuts = StepBreaks(inputs, options.input_tolerance);
  for (const Eigen::Index j : joins)
    if (j > 0 && j < n) cuts.push_back(j);
  std::ranges::sort(cuts);
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  cuts.insert(cuts.begin(), 0);
  cuts.push_back(n);
  report.stretches = static_cast<int>(cuts.size()) - 1;
  const double dt =
      joins.empty() ? (t(n - 1) - t(0)) / static_cast<double>(n - 1) : MedianInterval(t);
  const auto half = std::max<Eigen::Index>(
      1, static_cast<Eigen::Index>(std::round(options.slope_window_s / (2 * dt))));
  std::vector<double> floor;
  for (const Eigen::VectorXd& x : states) {
    report.noise_sd.push_back(EstimateNoiseSd(x));
    floor.push_back(options.scale_floor * x.cwiseAbs().maxCoeff());
  }
  std::vector<bool> settled(n);
  for (size_t c = 0; c + 1 < cuts.size(); ++c) {
    const Eigen::Index a = cuts[c], b = cuts[c + 1] - 1;
    if (t(b) - t(a) < options.min_window_s) continue;
    std::fill(settled.begin() + a, settled.begin() + b + 1, true);
    for (size_t i = 0; i < states.size(); ++i)
      MarkSettled(t, states[i], a, b, half, report.noise_sd[i], floor[i], options, settled);
    bool found = false;
    for (Eigen::Index last = b; last >= a;) {  // the last settled run that is long enough
      while (last >= a && !settled[last]) --last;
      if (last < a) break;
      Eigen::Index first = last;
      while (first > a && settled[first - 1]) --first;
      if (t(last) - t(first) >= options.min_window_s) {
        const bool constant = InputsHeld(inputs, first, last, options.input_tolerance);
        if (constant) report.windows.push_back({first, last});
        report.drifting += !constant;
        found = constant;
        break;
      }
      last = first - 1;
    }
    if (found || options.full_turn_state < 0 ||
        options.full_turn_state >= static_cast<int>(states.size()))
      continue;
    const Eigen::Index first = LastFullTurn(t, states[options.full_turn_state], a, b);
    if (first >= 0 && InputsHeld(inputs, first, b, options.input_tolerance)) {
      report.windows.push_back({first, b});
      ++report.full_turns;
    }
  }
  return report;
}

}  // namespace usvid::eb_lr
