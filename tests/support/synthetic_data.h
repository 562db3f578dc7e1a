// Synthetic data with its ground truth, for the tests of every method: a maneuver simulated on a
// vessel with seeded noise on the states, and the vessel's true right-hand side at clean data.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <string>

#include "maneuvers/maneuver_factory.h"
#include "sensors/noise.h"
#include "simulation/vessel_simulator.h"

namespace usvid::testing {

// `maneuver` on `vessel` for `seconds` at 20 Hz, noise on the states as a fraction of each
// state's standard deviation; the seed drives both the maneuver and the noise.
inline Dataset Simulate(const std::string& vessel, const std::string& maneuver, double seconds,
                        double noise, uint64_t seed) {
  const VesselSimulator& sim = FindVessel(vessel);
  auto m = MakeManeuver(maneuver, sim.Info().actuation, seconds, seed);
  Dataset d = sim.RunManeuver(*m, sim.Info().default_params, {}, RunOptions{}).data;
  AddGaussianNoise(d, sim.Info().states, noise, seed);
  return d;
}

// The vessel's true derivative of state `index` at every row of clean data (inputs held).
template <typename V>
Eigen::VectorXd TrueDerivative(const Dataset& d, int index) {
  Eigen::VectorXd out(d.rows());
  for (Eigen::Index k = 0; k < d.rows(); ++k) {
    std::array<double, V::kStates> x, dx;
    std::array<double, V::kInputs> u;
    for (int i = 0; i < V::kStates; ++i) x[i] = d[std::string(V::kStateNames[i])](k);
    for (int i = 0; i < V::kInputs; ++i) u[i] = d[std::string(V::kInputNames[i])](k);
    V::template Derivative<double>(x.data(), u.data(), V::kDefaultParams.data(), {}, dx.data());
    out(k) = dx[index];
  }
  return out;
}

// ||prediction - truth|| / ||truth||.
inline double RelativeError(const Eigen::VectorXd& prediction, const Eigen::VectorXd& truth) {
  return std::sqrt((prediction - truth).squaredNorm() / truth.squaredNorm());
}

}  // namespace usvid::testing
