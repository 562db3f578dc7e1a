// Leave-one-run-out cross-validation of a suite on measured data ("cv": "runs" in the suite,
// usvid compare --cv runs; docs/compare.md#cross-validation-over-runs). The runs are every data
// entry, training and test: a test entry is one run, and so is each file of a training entry,
// read with its entry's format, column map, cut and maneuver. Each run R is left out in turn:
// the fold "all but R" fits every method on the other runs jointly (core/records.h) and scores
// it on R alone (free run, horizons, and the closed-loop criteria of R's "maneuver"), so no run
// is both trained on and tested in one cell. A suite of n runs is n folds x its methods.
//
// The cell store keeps the folds apart (a job's id names its fold), while the rows carry one
// training label, kLeaveOneRunOut: the verdict (harness/verdict.h) then ranks the methods over
// all n held-out runs as paired blocks, and the tables pool them.
#pragma once

#include <string>
#include <vector>

#include "harness/suite.h"

namespace usvid {

inline constexpr char kLeaveOneRunOut[] = "leave-one-run-out";
inline constexpr char kCrossValidationRuns[] = "runs";  // the one kind there is

// The fold that leaves `run` out: "all but <run>".
std::string FoldName(const std::string& run);

// Turns a parsed suite on measured data into its folds: cv.given_* keep the entries as given,
// test_data becomes the runs (one file each) and test_maneuvers their names, train_maneuvers
// the folds' names and cv.held_out each fold's run. A run of a training entry of several files
// is named "<entry name>: <file stem>". Throws InputError, one line naming `file`, for a kind
// other than "runs", fewer than two runs, two runs of one name, or one file's same rows listed
// twice (a run left out would still be trained on).
void ExpandCrossValidation(Suite& suite, const std::string& kind, const std::string& file);

// The test maneuvers `train`'s fits are scored on: every one, or in a cross-validated suite the
// run its fold leaves out.
std::vector<std::string> ScoredTests(const Suite& suite, const std::string& train);

// The runs fold `train` fits on, in the suite's order: every run but the one it leaves out.
std::vector<std::string> FoldTrainingRuns(const Suite& suite, const std::string& train);

// The training label a row of `train` carries: kLeaveOneRunOut for a fold, else `train`.
std::string TrainingLabel(const Suite& suite, const std::string& train);

// The distinct training labels of the suite's rows, in order (one for a cross-validated suite).
std::vector<std::string> TrainingLabels(const Suite& suite);

}  // namespace usvid
