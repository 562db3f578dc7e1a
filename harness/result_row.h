// One result of a comparison: a method's model, fitted on one training maneuver, scored in free
// run on one held-out test maneuver. Rows are what results.json, the tables and the report are
// made of, and what a resumed or MPI-distributed run stores and exchanges.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace usvid {

struct FreeRun;           // metrics/free_run.h
struct ClosedLoopReplay;  // metrics/closed_loop_replay.h

struct ResultRow {
  std::string vessel, train_maneuver, test_maneuver, method;
  std::string inputs;  // what drove the model: "forces waterjet: tau_x,..." or "throttle,..."
  double noise = 0.0;
  uint64_t seed = 1, test_seed = 1;
  std::map<std::string, double> fit_percent;  // per identified state
  std::map<std::string, double> nrmse;
  std::map<std::string, double> channel_fit_percent;  // every channel of the free run (psi too)
  double mean_fit_percent = 0.0;
  std::map<std::string, double> regime_fit_percent;  // mean over states, per speed regime
  // Per prediction horizon ("5", "30" s, "all": the free run), the mean fit % over the states.
  std::map<std::string, double> horizon_fit_percent;
  std::optional<double> valid_prediction_s;     // the free run's valid prediction time
  std::map<std::string, double> derivative_r2;  // per state: the equation against the data
  bool diverged = false;
  double diverged_at_s = 0.0;
  std::string diverged_channel;  // which channel left its bound (metrics/free_run.h)
  // The closed-loop replay of the test maneuver (metrics/closed_loop_replay.h ClosedLoopScore):
  // its criteria against the record's, or why it could not be replayed.
  nlohmann::json closed_loop = nlohmann::json::object();
  double fit_seconds = 0.0;
  int terms = 0;                          // complexity: additive terms over all equations
  std::optional<double> precision;        // structure recovery, mean over states, where the true
  std::optional<double> recall;           //   terms are known (msd, odin3dof)
  std::optional<double> parameter_error;  // largest relative error of named true parameters
  std::string status = "ok";              // or "failed: why"
  nlohmann::json model;  // the fitted model (kept in memory for the report, not written)
  // The free run the row was scored on, where the report draws it (ReportDrawsFreeRun,
  // run_suite.h): kept in memory, not written. A row read back from a resumed run's cells or
  // from another MPI rank has none, and the report runs the model again.
  std::shared_ptr<const FreeRun> free_run;
  // Likewise the closed-loop replay its criteria were read from (closed_loop), on measured data,
  // for the report's plan views (harness/plan_view.h).
  std::shared_ptr<const ClosedLoopReplay> replay;

  // The row as results.json holds it (no model; a failed row only says why).
  nlohmann::json ToJson() const;
  // Everything but the model (a cell keeps that once for its rows, cell_store.h): what a
  // resumed run reads back and MPI ranks exchange.
  nlohmann::json ToCellJson() const;
  static ResultRow FromCellJson(const nlohmann::json& j);
};

}  // namespace usvid
