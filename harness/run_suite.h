// Runs a comparison suite: every fit job (suite.h) trains its method on simulated data, and the
// model is scored in free run on every test maneuver simulated with another seed (seed + 1000),
// so no score is on data the model was fitted on. Jobs run in parallel (OpenMP, one thread per
// job, each deterministic from its seed), rows come out in job order, so results do not depend
// on the thread count. A job that fails is a row saying why, not a stopped run.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/dataset.h"
#include "harness/result_row.h"
#include "harness/suite.h"

namespace usvid {

// The data a suite trains or tests on: `maneuver` on `vessel` (step grids run to the end of
// their grid), noise on every measured channel, all from `seed`.
Dataset SimulateForSuite(const std::string& vessel, const std::string& maneuver, double seconds,
                         double noise, uint64_t seed);

// Every cell (fit job) of the suite, in one process; rows in job order.
std::vector<ResultRow> RunSuite(const Suite& suite, int threads,
                                const std::function<void(const std::string&)>& progress = {});

// The cells jobs[which[k]], in parallel; result k holds the rows of jobs[which[k]]. `done` is
// called as each cell finishes (one call at a time, in completion order); an exception it
// throws ends the run once the running cells are done (InputError with its message).
std::vector<std::vector<ResultRow>> RunCells(
    const Suite& suite, const std::vector<FitJob>& jobs, const std::vector<size_t>& which,
    int threads, const std::function<void(size_t, const std::vector<ResultRow>&)>& done = {});

// The progress line of a finished cell: "[finished/total] job id", and why when its fit failed.
std::string CellProgress(size_t finished, size_t total, const FitJob& job,
                         const std::vector<ResultRow>& rows);

}  // namespace usvid
