#include "design/information.h"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/error.h"
#include "core/model_view.h"
#include "design/eb_lr_information.h"
#include "design/method_problem.h"
#include "maneuvers/maneuver_factory.h"
#include "methods/eb_lr/eb_lr.h"
#include "sensors/noise.h"
#include "simulation/vessel_simulator.h"

namespace usvid::design {
namespace {

double Spread(const Eigen::VectorXd& y) {
  return std::sqrt((y.array() - y.mean()).square().mean());
}

// The criteria of the covariance `cov` (relative units) of the parameters of interest.
void SetCriteria(const Eigen::MatrixXd& cov, const std::vector<std::string>& names,
                 ManeuverInformation& m) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(cov);
  // Information along each direction, largest variance (least information) first.
  const Eigen::VectorXd mu = eig.eigenvalues().cwiseMax(eig.eigenvalues().maxCoeff() * 1e-300);
  m.log_det = -mu.array().log().sum();
  m.trace_inverse = cov.trace();
  m.condition_number = mu.maxCoeff() / mu.minCoeff();
  m.weakest.clear();
  const Eigen::Index n = mu.size();
  for (Eigen::Index k = n - 1; k >= std::max<Eigen::Index>(0, n - 2); --k) {
    WeakDirection w;
    w.eigenvalue = 1.0 / mu(k);
    for (size_t i = 0; i < names.size(); ++i)
      w.parameters.emplace_back(names[i], eig.eigenvectors()(static_cast<Eigen::Index>(i), k));
    std::sort(w.parameters.begin(), w.parameters.end(),
              [](const auto& a, const auto& b) { return std::abs(a.second) > std::abs(b.second); });
    m.weakest.push_back(std::move(w));
  }
}

void CheckFocus(const DesignProblem& problem, const std::vector<std::string>& names) {
  for (const std::string& p : problem.focus)
    if (std::find(names.begin(), names.end(), p) == names.end()) {
      std::string list;
      for (const std::string& k : names) list += (list.empty() ? "" : ", ") + k;
      throw InputError("design: --parameters: " + problem.method + " on " + problem.vessel.Name() +
                       " has no free parameter '" + p + "' (free: " + list + ")");
    }
}

}  // namespace

void CheckProblem(const DesignProblem& problem) {
  const MethodProblem method = MethodProblemOf(problem.vessel, problem.method);
  // refit's free parameters are known once its problem is built (InformationOf checks them).
  if (!method.names.empty()) CheckFocus(problem, method.names);
}

Dataset SimulateManeuver(const VesselRef& vessel, const std::string& spec, double seconds,
                         uint64_t seed) {
  if (!(seconds > 0.0) || !std::isfinite(seconds))
    throw InputError("design: --duration must be positive, not " + std::to_string(seconds));
  const VesselSimulator& sim = vessel.Simulator();
  auto maneuver = MakeManeuver(spec, sim.Info().actuation, seconds, seed);
  return sim.RunManeuver(*maneuver, sim.Info().default_params, {}, RunOptions{}).data;
}

NoiseModel ReferenceNoise(const Dataset& reference, const std::vector<std::string>& channels,
                          double noise) {
  if (!(noise > 0.0) || !std::isfinite(noise))
    throw InputError("design: --noise must be positive (a fraction of each channel's spread)");
  NoiseModel out;
  for (const std::string& c : channels) {
    if (!reference.Has(c)) continue;
    const double spread = Spread(reference[c]);
    out[c] = noise * (spread > 0.0 ? spread : 1.0);
  }
  return out;
}

Dataset NoisyRun(const DesignProblem& problem, const std::string& maneuver, uint64_t noise_seed) {
  Dataset data = SimulateManeuver(problem.vessel, maneuver, problem.seconds, 1);
  uint64_t stream = 0;
  for (const auto& [channel, sd] : problem.noise) {
    if (!data.Has(channel)) continue;
    const double spread = Spread(data[channel]);
    if (spread > 0.0) AddGaussianNoise(data, {channel}, sd / spread, noise_seed * 1000 + stream++);
  }
  return data;
}

ManeuverInformation InformationOf(const DesignProblem& problem, const std::string& maneuver,
                                  uint64_t seed) {
  const auto t0 = std::chrono::steady_clock::now();
  const MethodProblem method = MethodProblemOf(problem.vessel, problem.method);
  RefitOptions o = method.refit;
  o.information_only = true;
  o.noise_sd = problem.noise;
  const Dataset data = SimulateManeuver(problem.vessel, maneuver, problem.seconds, seed);
  const VesselInfo& info = problem.vessel.Info();
  const RefitResult r = RefitVessel(problem.vessel, data, info.default_params, o);

  ManeuverInformation m;
  m.maneuver = maneuver;
  m.names = method.names.empty() ? r.free : method.names;
  m.information = r.information;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(m.information);
  if (m.names.empty() || !(eig.eigenvalues().maxCoeff() > 0.0))
    throw InputError("design: " + maneuver + " on " + problem.vessel.Name() +
                     " carries no information about the parameters of " + problem.method);
  // Directions with no information at all keep a finite, huge sd (1e-300 of the largest).
  const Eigen::VectorXd lambda = eig.eigenvalues().cwiseMax(eig.eigenvalues().maxCoeff() * 1e-300);
  const Eigen::MatrixXd bound =
      eig.eigenvectors() * lambda.cwiseInverse().asDiagonal() * eig.eigenvectors().transpose();
  // The method's own covariance: the bound, but for eb-lr, which uses part of the record.
  Eigen::MatrixXd cov = bound;
  const Dataset noisy = NoisyRun(problem, maneuver, 1);
  const Probe probe = ProbeFit(problem.vessel, problem.method, noisy);
  m.unusable = probe.unusable;
  if (problem.method == eb_lr::kMethodName && m.unusable.empty()) {
    std::vector<std::pair<double, double>> windows;
    for (const auto& w : ModelView(probe.model).Section("eb_lr").at("steady_windows"))
      windows.emplace_back(w.at("start_s"), w.at("end_s"));
    cov = EbLrCovariance(r.information, data, noisy, windows, problem.noise);
    m.information = cov.inverse();
  }
  for (size_t i = 0; i < r.free.size(); ++i) {
    const size_t p =
        std::find(info.params.begin(), info.params.end(), r.free[i]) - info.params.begin();
    const double value = info.default_params[p];
    const auto ii = static_cast<Eigen::Index>(i);
    const double scale = value != 0.0 ? std::abs(value) : 1.0;
    m.values.push_back(value);
    m.relative_sd.push_back(std::sqrt(cov(ii, ii)));
    m.sd.push_back(m.relative_sd.back() * scale);
    m.shooting_sd.push_back(std::sqrt(bound(ii, ii)) * scale);
  }
  CheckFocus(problem, m.names);
  std::vector<Eigen::Index> focus;
  std::vector<std::string> focus_names;
  for (size_t i = 0; i < m.names.size(); ++i)
    if (problem.focus.empty() ||
        std::find(problem.focus.begin(), problem.focus.end(), m.names[i]) != problem.focus.end()) {
      focus.push_back(static_cast<Eigen::Index>(i));
      focus_names.push_back(m.names[i]);
    }
  SetCriteria(cov(focus, focus), focus_names, m);
  m.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return m;
}

}  // namespace usvid::design
