// Runs a comparison suite: every fit job (suite.h) trains its method on simulated data, and the
// model is scored in free run on every test maneuver simulated with another seed (seed + 1000),
// so no score is on data the model was fitted on. Jobs run in parallel (OpenMP, one thread per
// job, each deterministic from its seed), rows come out in job order, so results do not depend
// on the thread count. A job that fails is a row saying why, not a stopped run.
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/dataset.h"
#include "harness/result_row.h"
#include "harness/suite.h"
#include "methods/identify_request.h"

namespace usvid {

// The data a suite trains or tests on: `maneuver` on `vessel` (step grids run to the end of
// their grid) under the suite's hidden effects, noise on every measured channel, then the
// sensors' rates, all from `seed`.
Dataset SimulateForSuite(const VesselRef& vessel, const std::string& maneuver, double seconds,
                         double noise, uint64_t seed, const SuiteConditions& conditions = {});

// Whether the report (report.h) draws the free run of `row`: the first noise level and seed, on
// a simulated suite's first test maneuver or on any test of measured data. Such rows keep the
// free run they were scored on (ResultRow::free_run), and on measured data the closed-loop
// replay (ResultRow::replay), so that the report need not run them again.
bool ReportDrawsFreeRun(const Suite& suite, const ResultRow& row);

// Every cell (fit job) of the suite, in one process; rows in job order.
std::vector<ResultRow> RunSuite(const Suite& suite, int threads,
                                const std::function<void(const std::string&)>& progress = {});

// Runs cells on `threads` OpenMP threads (0: OpenMP's default), each thread taking the next job
// index from `next` (called by one thread at a time) until it returns nothing: the rows of every
// cell run here, by job index. `done` is called as each cell finishes (one call at a time); an
// exception it throws ends the run once the running cells are done (InputError, its message).
std::map<size_t, std::vector<ResultRow>> RunCells(
    const Suite& suite, const std::vector<FitJob>& jobs, int threads,
    const std::function<std::optional<size_t>()>& next,
    const std::function<void(size_t, const std::vector<ResultRow>&)>& done = {});

// `cells` (job indices) reordered to start the costliest fits first (Method::relative_cost;
// a method outside the registry counts as 1), ties in their given order. Which thread runs a cell
// does not change its rows, so only the run's wall time changes.
std::vector<size_t> SlowestFirst(const std::vector<FitJob>& jobs, std::vector<size_t> cells);

// The progress line of a finished cell: "[finished/total] job id", and why when its fit failed.
std::string CellProgress(size_t finished, size_t total, const FitJob& job,
                         const std::vector<ResultRow>& rows);

}  // namespace usvid
