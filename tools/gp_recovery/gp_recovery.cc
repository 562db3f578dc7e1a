// usvid_gp_recovery: how often GP-SR recovers odin3dof's equations, over seeds (docs/gp.md).
//
// For each seed: odin3dof random steps (--seconds, --noise as a fraction of each state's
// standard deviation, the seed driving maneuver and noise), `identify --method gp` through the
// same code as the command line, and each identified right-hand side compared with the true one
// (docs/vessels/odin3dof.md) on a clean held-out multisine run (300 s, seed 1000 + seed):
//   error = ||f_hat(x, tau) - f(x, tau)|| / ||f(x, tau)||   per equation.
// A seed recovers the model when all three errors are within --within. Prints a markdown table
// row per seed and a summary line; with --json, the same as JSON.
#include <CLI/CLI.hpp>
#include <array>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/expression.h"
#include "core/model_view.h"
#include "maneuvers/maneuver_factory.h"
#include "methods/gp/gp_identify.h"
#include "methods/identify.h"
#include "sensors/noise.h"
#include "simulation/vessel_simulator.h"
#include "simulators/odin3dof.h"

namespace usvid {
namespace {

Dataset Simulate(const std::string& maneuver, double seconds, double noise, uint64_t seed) {
  const VesselSimulator& sim = FindVessel("odin3dof");
  auto m = MakeManeuver(maneuver, sim.Info().actuation, seconds, seed);
  Dataset d = sim.RunManeuver(*m, sim.Info().default_params, {}, RunOptions{}).data;
  AddGaussianNoise(d, sim.Info().states, noise, seed);
  return d;
}

// The true u', v', r' at every row of clean data.
std::array<Eigen::VectorXd, 3> TrueRightHandSides(const Dataset& d) {
  std::array<Eigen::VectorXd, 3> out;
  for (auto& o : out) o.resize(d.rows());
  for (Eigen::Index k = 0; k < d.rows(); ++k) {
    std::array<double, Odin3Dof::kStates> x, dx;
    std::array<double, Odin3Dof::kInputs> u;
    for (int i = 0; i < Odin3Dof::kStates; ++i) x[i] = d[std::string(Odin3Dof::kStateNames[i])](k);
    for (int i = 0; i < Odin3Dof::kInputs; ++i) u[i] = d[std::string(Odin3Dof::kInputNames[i])](k);
    Odin3Dof::Derivative<double>(x.data(), u.data(), Odin3Dof::kDefaultParams.data(), {},
                                 dx.data());
    for (int s = 0; s < 3; ++s) out[s](k) = dx[3 + s];
  }
  return out;
}

int Run(int argc, char** argv) {
  CLI::App app{"GP-SR recovery of odin3dof's equations over seeds"};
  int seeds = 10, threads = 2;
  double noise = 0.005, seconds = 900, within = 0.02;
  std::string operators = "+,-,*,abs", preset = "default";
  std::optional<double> threshold;
  bool json = false;
  app.add_option("--seeds", seeds, "Seeds 1..N");
  app.add_option("--noise", noise, "Noise on the states (fraction of each one's sd)");
  app.add_option("--seconds", seconds, "Length of the training run");
  app.add_option("--operators", operators, "GP operators");
  app.add_option("--preset", preset, "default or report");
  app.add_option("--ols-threshold", threshold, "Overrides the preset's term selection");
  app.add_option("--within", within, "Largest relative error that counts as recovered");
  app.add_option("--threads", threads, "OpenMP threads");
  app.add_flag("--json", json, "JSON instead of markdown");
  CLI11_PARSE(app, argc, argv);

  nlohmann::json rows = nlohmann::json::array();
  int recovered = 0;
  double total_seconds = 0.0;
  if (!json)
    std::printf(
        "| seed | u' | v' | r' | seconds (3 equations) |\n| --- | --- | --- | --- | --- |\n");
  for (int seed = 1; seed <= seeds; ++seed) {
    const Dataset train = Simulate("random-steps", seconds, noise, static_cast<uint64_t>(seed));
    const Dataset held = Simulate("multisine", 300, 0.0, 1000 + static_cast<uint64_t>(seed));
    IdentifyRequest r;
    r.method = gp::kMethodName;
    r.vessel = "odin3dof";
    r.options = {{"preset", preset}, {"operators", operators}};
    if (threshold) r.options["ols_threshold"] = *threshold;
    r.seed = static_cast<uint64_t>(seed);
    r.threads = threads;
    const nlohmann::json model = Identify(train, r);
    const ModelView view(model);
    const auto truth = TrueRightHandSides(held);
    nlohmann::json row = {{"seed", seed}, {"seconds", view.TrainSeconds()}};
    bool ok = true;
    std::array<double, 3> err{};
    int s = 0;
    for (const char* state : {"u", "v", "r"}) {
      const std::string eq = view.Equation(state).value_or("0");
      const Eigen::VectorXd f = Expression::Parse(eq).Evaluate(held);
      err[s] = std::sqrt((f - truth[s]).squaredNorm() / truth[s].squaredNorm());
      ok &= err[s] <= within;
      row[state] = {{"error", err[s]}, {"equation", eq}};
      ++s;
    }
    recovered += ok;
    total_seconds += view.TrainSeconds();
    rows.push_back(row);
    if (!json)
      std::printf("| %d | %.2f %% | %.2f %% | %.2f %% | %.1f |\n", seed, 100 * err[0], 100 * err[1],
                  100 * err[2], view.TrainSeconds());
    std::fflush(stdout);
  }
  if (json) {
    std::cout << nlohmann::json{{"noise", noise},   {"operators", operators}, {"preset", preset},
                                {"within", within}, {"recovered", recovered}, {"seeds", seeds},
                                {"runs", rows}}
                     .dump(2)
              << '\n';
  } else {
    std::printf("\nrecovered (all three within %.1f %%): %d of %d; mean %.1f s per model\n",
                100 * within, recovered, seeds, total_seconds / seeds);
  }
  return 0;
}

}  // namespace
}  // namespace usvid

int main(int argc, char** argv) {
  try {
    return usvid::Run(argc, argv);
  } catch (const usvid::InputError& e) {
    std::cerr << "usvid_gp_recovery: " << e.what() << '\n';
    return 2;
  }
}
