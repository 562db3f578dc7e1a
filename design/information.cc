#include "design/information.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/error.h"
#include "maneuvers/maneuver_factory.h"
#include "simulation/vessel_simulator.h"

namespace usvid::design {

RefitOptions MethodProblem(const std::string& vessel, const std::string& method) {
  FindVessel(vessel);  // throws for an unknown vessel
  RefitOptions o;
  if (method == "refit") return o;
  if (method == "fossen-ceres") {
    if (vessel != "odin3dof")
      throw InputError("design: fossen-ceres is designed for odin3dof only (its model is that "
                       "vessel's), not " + vessel);
    o.free = FindVessel(vessel).Info().params;  // all 10
    o.prior_sd = 1e9;                            // none
    o.segment_s = 10.0;                          // fossen-ceres' shooting segments
    return o;
  }
  if (method == "gp" || method == "sindy")
    throw InputError("design: --method " + method +
                     " has no parameters to design a maneuver for (use refit or fossen-ceres)");
  throw InputError("design: --method '" + method + "' is not supported (known: refit, fossen-ceres)");
}

Dataset SimulateManeuver(const std::string& vessel, const std::string& spec, double seconds,
                         uint64_t seed) {
  if (!(seconds > 0.0) || !std::isfinite(seconds))
    throw InputError("design: --duration must be positive, not " + std::to_string(seconds));
  const VesselSimulator& sim = FindVessel(vessel);
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
    const Eigen::VectorXd& y = reference[c];
    const double spread = std::sqrt((y.array() - y.mean()).square().mean());
    out[c] = noise * (spread > 0.0 ? spread : 1.0);
  }
  return out;
}

ManeuverInformation InformationOf(const std::string& vessel, const std::string& method,
                                  const std::string& maneuver, double seconds,
                                  const NoiseModel& noise, uint64_t seed) {
  const auto t0 = std::chrono::steady_clock::now();
  RefitOptions o = MethodProblem(vessel, method);
  o.information_only = true;
  o.noise_sd = noise;
  const Dataset data = SimulateManeuver(vessel, maneuver, seconds, seed);
  const VesselInfo& info = FindVessel(vessel).Info();
  const RefitResult r = RefitVessel(vessel, data, info.default_params, o);

  ManeuverInformation m;
  m.maneuver = maneuver;
  m.names = r.free;
  m.information = r.information;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(m.information);
  if (m.names.empty() || !(eig.eigenvalues().maxCoeff() > 0.0))
    throw InputError("design: " + maneuver + " on " + vessel +
                     " carries no information about the parameters of " + method);
  // Directions with no information at all keep a finite, huge sd (1e-300 of the largest).
  const Eigen::VectorXd lambda = eig.eigenvalues().cwiseMax(eig.eigenvalues().maxCoeff() * 1e-300);
  const Eigen::MatrixXd cov = eig.eigenvectors() * lambda.cwiseInverse().asDiagonal() *
                              eig.eigenvectors().transpose();
  m.log_det = lambda.array().log().sum();
  m.trace_inverse = cov.trace();
  m.condition_number = lambda.maxCoeff() / lambda.minCoeff();
  for (size_t i = 0; i < m.names.size(); ++i) {
    const size_t p = std::find(info.params.begin(), info.params.end(), m.names[i]) -
                     info.params.begin();
    const double value = info.default_params[p];
    const double rel = std::sqrt(cov(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(i)));
    m.values.push_back(value);
    m.relative_sd.push_back(rel);
    m.sd.push_back(rel * (value != 0.0 ? std::abs(value) : 1.0));
  }
  for (Eigen::Index k = 0; k < std::min<Eigen::Index>(2, lambda.size()); ++k) {
    WeakDirection w;
    w.eigenvalue = eig.eigenvalues()(k);
    for (size_t i = 0; i < m.names.size(); ++i)
      w.parameters.emplace_back(m.names[i], eig.eigenvectors()(static_cast<Eigen::Index>(i), k));
    std::sort(w.parameters.begin(), w.parameters.end(),
              [](const auto& a, const auto& b) { return std::abs(a.second) > std::abs(b.second); });
    m.weakest.push_back(std::move(w));
  }
  m.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return m;
}

}  // namespace usvid::design
