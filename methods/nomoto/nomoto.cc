#include "methods/nomoto/nomoto.h"

#include <ceres/ceres.h>

#include <Eigen/QR>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <utility>

#include "core/error.h"
#include "core/parse_number.h"
#include "core/stretches.h"
#include "methods/parameter_sd.h"

namespace usvid::nomoto {
namespace {

constexpr double kMaxStep = 0.1;       // RK4 substep bound [s]
constexpr double kUnstableT = 1000.0;  // T reported for an unstable equation-error fit [s]

double Sd(const Eigen::VectorXd& v) {
  const double sd = std::sqrt((v.array() - v.mean()).square().mean());
  return sd > 0 ? sd : 1.0;
}

int Substeps(double dt) { return std::max(1, static_cast<int>(std::ceil(dt / kMaxStep - 1e-9))); }

// One shooting segment: r rolled out from the free start r0 over the segment's rows, the input
// held over each sample interval; one residual per row (the first compares r0 itself).
struct SegmentResidual {
  std::vector<double> t, input, measured;
  double scale = 1.0;

  template <typename S>
  bool operator()(const S* p, const S* r0, S* res) const {
    const S& gain = p[0];
    const S& tau = p[1];
    const S& offset = p[2];
    S r = r0[0];
    res[0] = (r - measured[0]) / scale;
    for (size_t k = 0; k + 1 < t.size(); ++k) {
      const int n = Substeps(t[k + 1] - t[k]);
      const double h = (t[k + 1] - t[k]) / n;
      const S target = gain * (input[k] - offset);
      const auto f = [&](const S& x) { return (target - x) / tau; };
      for (int i = 0; i < n; ++i) {
        const S k1 = f(r), k2 = f(r + 0.5 * h * k1), k3 = f(r + 0.5 * h * k2), k4 = f(r + h * k3);
        r += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
      }
      res[k + 1] = (r - measured[k + 1]) / scale;
    }
    return true;
  }
};

void Require(const Dataset& d, const std::string& channel, const std::string& rate,
             const std::string& input) {
  if (!d.Has(channel))
    throw InputError("nomoto: the data need channel '" + channel + "' (state " + rate +
                     " with its derivative " + rate + "_dot; yaw input " + input + ")");
}

// Step 1: r' = a r + b delta + c by linear least squares.
void FitEquationError(const Dataset& d, const std::string& rate, const std::string& input,
                      NomotoFit& fit) {
  Eigen::MatrixXd x(d.rows(), 3);
  x << d[rate], d[input], Eigen::VectorXd::Ones(d.rows());
  const Eigen::Vector3d abc = x.colPivHouseholderQr().solve(d[rate + "_dot"]);
  const double a = abc(0), b = abc(1), c = abc(2);
  std::ostringstream note;
  note << "equation error: " << rate << "_dot = a*" << rate << " + b*" << input
       << " + c with a = " << a << ", b = " << b << ", c = " << c;
  fit.notes.push_back(note.str());
  if (a < 0) {
    fit.equation_error_T = -1.0 / a;
  } else {
    fit.equation_error_T = kUnstableT;
    fit.notes.push_back("equation error: a >= 0 is an unstable model; T clamped to " +
                        FormatNumber(kUnstableT) + " s to start the output-error fit");
  }
  fit.equation_error_K = b * fit.equation_error_T;
  fit.equation_error_delta0 = -c / b;
  if (!std::isfinite(fit.equation_error_delta0)) {
    fit.equation_error_delta0 = 0.0;
    fit.notes.push_back("equation error: " + input + " has no effect on " + rate +
                        " (b = 0); delta0 started at 0");
  }
}

// The shooting segments, [first, last] rows of at most segment_s each, none across a gap
// (core/stretches.h): no segment of one row (it joins the one before; after a gap, none).
std::vector<std::pair<Eigen::Index, Eigen::Index>> ShootingSegments(const Eigen::VectorXd& t,
                                                                    double gap, double segment_s) {
  std::vector<std::pair<Eigen::Index, Eigen::Index>> segments;
  const auto rows = t.size();
  for (Eigen::Index first = 0; first < rows;) {
    Eigen::Index last = first;
    while (last + 1 < rows && t(last + 1) - t(first) < segment_s && t(last + 1) - t(last) <= gap)
      ++last;
    const bool after_gap = first > 0 && t(first) - t(first - 1) > gap;
    if (last == first && !segments.empty()) {
      if (!after_gap) segments.back().second = last;
    } else {
      segments.emplace_back(first, last);
    }
    first = last + 1;
  }
  return segments;
}

// The smallest T the fit may take: RK4 on r' = -r/T is stable for h/T < 2.78, so half the largest
// substep keeps every rollout stable.
double SmallestT(const Eigen::VectorXd& t, double gap) {
  double max_step = 0.0;
  for (Eigen::Index k = 0; k + 1 < t.size(); ++k)
    if (t(k + 1) - t(k) <= gap)
      max_step = std::max(max_step, (t(k + 1) - t(k)) / Substeps(t(k + 1) - t(k)));
  return std::max(1e-3, 0.5 * max_step);
}

// The parameters' standard deviations from Ceres' covariance into `fit` (0, with a note, when
// it is not available).
void AddParameterSds(ceres::Problem& problem, double* p, const ceres::Solver::Summary& summary,
                     NomotoFit& fit) {
  ceres::Covariance covariance{ceres::Covariance::Options{}};
  const std::vector<std::pair<const double*, const double*>> blocks = {{p, p}};
  if (!covariance.Compute(blocks, &problem)) {
    fit.notes.push_back("output error: covariance not available (standard deviations 0)");
    return;
  }
  double c[9];
  covariance.GetCovarianceBlock(p, p, c);
  // The residuals are in units of sd(r): scaled by the residual variance per degree of freedom.
  const std::vector<double> sd = ParameterSds(c, 3, summary);
  fit.sd_K = sd[0];
  fit.sd_T = sd[1];
  fit.sd_delta0 = sd[2];
}

}  // namespace

NomotoFit FitNomoto(const PreparedData& prepared, const std::string& rate,
                    const std::string& yaw_input, double segment_s) {
  const auto start = std::chrono::steady_clock::now();
  const Dataset& d = prepared.data;
  for (const std::string& c : {rate, rate + "_dot", yaw_input}) Require(d, c, rate, yaw_input);
  if (!(segment_s > 0)) throw InputError("nomoto: the segment length must be positive");
  if (d.rows() < 10) throw InputError("nomoto: the data need at least 10 rows");
  if ((d[yaw_input].array() == d[yaw_input](0)).all())
    throw InputError("nomoto: the yaw input '" + yaw_input +
                     "' is constant; K is not identifiable");

  NomotoFit fit;
  FitEquationError(d, rate, yaw_input, fit);

  // Step 2: output error by multiple shooting.
  const Eigen::VectorXd& t = d.t();
  const Eigen::VectorXd& input = d[yaw_input];
  const Eigen::VectorXd& measured = d[d.Has(rate + "_raw") ? rate + "_raw" : rate];
  const Eigen::VectorXd& smoothed = d[rate];
  const double gap = GapLimit(t, kGridGapFactor);
  const std::vector<std::pair<Eigen::Index, Eigen::Index>> segments =
      ShootingSegments(t, gap, segment_s);
  const double min_t = SmallestT(t, gap);

  double p[3] = {fit.equation_error_K, std::max(fit.equation_error_T, min_t),
                 fit.equation_error_delta0};
  std::vector<double> r0(segments.size());
  ceres::Problem problem;
  const double scale = Sd(measured);
  for (size_t j = 0; j < segments.size(); ++j) {
    auto* seg = new SegmentResidual;
    for (Eigen::Index k = segments[j].first; k <= segments[j].second; ++k) {
      seg->t.push_back(t(k));
      seg->input.push_back(input(k));
      seg->measured.push_back(measured(k));
    }
    seg->scale = scale;
    r0[j] = smoothed(segments[j].first);
    const int residuals = static_cast<int>(seg->t.size());
    problem.AddResidualBlock(
        new ceres::AutoDiffCostFunction<SegmentResidual, ceres::DYNAMIC, 3, 1>(seg, residuals),
        nullptr, p, &r0[j]);
  }
  problem.SetParameterLowerBound(p, 1, min_t);

  ceres::Solver::Options so;
  so.minimizer_type = ceres::TRUST_REGION;
  so.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  so.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  so.max_num_iterations = 100;
  so.function_tolerance = 1e-12;
  so.parameter_tolerance = 1e-10;
  ceres::Solver::Summary summary;
  ceres::Solve(so, &problem, &summary);
  fit.termination = ceres::TerminationTypeToString(summary.termination_type) + std::string(": ") +
                    summary.message;
  fit.converged = summary.termination_type == ceres::CONVERGENCE;
  fit.K = p[0];
  fit.T = p[1];
  fit.delta0 = p[2];
  std::ostringstream note;
  note << "output error: " << segments.size() << " segments of up to " << segment_s
       << " s, RMS error " << scale * std::sqrt(2.0 * summary.final_cost / summary.num_residuals)
       << " (" << (d.Has(rate + "_raw") ? rate + "_raw" : rate) << "), "
       << summary.iterations.size() << " iterations";
  fit.notes.push_back(note.str());
  if (fit.T <= min_t * (1 + 1e-6))
    fit.notes.push_back("output error: T at its lower bound " + FormatNumber(min_t) + " s");
  if (!fit.converged) fit.notes.push_back("output error: " + fit.termination);

  AddParameterSds(problem, p, summary, fit);
  fit.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return fit;
}

nlohmann::json NomotoEquations(const NomotoFit& fit, const std::string& rate,
                               const std::string& yaw_input) {
  return {{rate, "(" + FormatNumber(fit.K) + "*(" + yaw_input + " - " + FormatNumber(fit.delta0) +
                     ") - " + rate + ")/" + FormatNumber(fit.T)}};
}

}  // namespace usvid::nomoto
