// Runs a comparison suite: every fit job (suite.h) trains its method on simulated data, and the
// model is scored in free run on every test maneuver simulated with another seed (seed + 1000),
// so no score is on data the model was fitted on. Jobs run in parallel (OpenMP, one thread per
// job, each deterministic from its seed), rows come out in job order, so results do not depend
// on the thread count. A job that fails is a row saying why, not a stopped run.
#pragma once

#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/dataset.h"
#include "harness/suite.h"

namespace usvid {

struct ResultRow {
  std::string vessel, train_maneuver, test_maneuver, method;
  double noise = 0.0;
  uint64_t seed = 1, test_seed = 1;
  std::map<std::string, double> fit_percent;  // per identified state
  std::map<std::string, double> nrmse;
  std::map<std::string, double> channel_fit_percent;  // every channel of the free run (psi too)
  double mean_fit_percent = 0.0;
  std::map<std::string, double> regime_fit_percent;  // mean over states, per speed regime
  bool diverged = false;
  double fit_seconds = 0.0;
  int terms = 0;                          // complexity: additive terms over all equations
  std::optional<double> precision;        // structure recovery, mean over states, where the true
  std::optional<double> recall;           //   terms are known (msd, odin3dof)
  std::optional<double> parameter_error;  // largest relative error of named true parameters
  std::string status = "ok";              // or "failed: why"
  nlohmann::json model;  // the fitted model (kept in memory for the report, not written)

  nlohmann::json ToJson() const;
};

// The data a suite trains or tests on: `maneuver` on `vessel` (step grids run to the end of
// their grid), noise on every measured channel, all from `seed`.
Dataset SimulateForSuite(const std::string& vessel, const std::string& maneuver, double seconds,
                         double noise, uint64_t seed);

std::vector<ResultRow> RunSuite(const Suite& suite, int threads,
                                const std::function<void(const std::string&)>& progress = {});

}  // namespace usvid
