// Which of GP's candidate equations to return: chosen by how the whole model free-runs, not by
// equation error alone. An equation that fits derivatives to 0.1 % can still make a model that
// drifts or blows up once its own outputs feed back into it.
//
// Each state with an equation has candidates (its search's Pareto front of held-out error
// against size, and its best individual). Each candidate is scored by its short-horizon
// simulation error on the validation rows: from every `horizon_s`-th second its state is
// integrated by RK4 from the measured value, over `horizon_s`, under the measured inputs
// (zero-order hold) and the measured values of every other variable; the score is the mean
// squared error divided by the state's variance. Each state is scored on its own, so that a wrong
// equation of one state cannot make a wrong one of another look right. The smallest candidate
// whose error is within one standard error (over segments) of the smallest is chosen (the
// one-standard-error rule: the largest candidates fit the validation part a little better by
// fitting the derivative estimate's errors). A segment that leaves
// the bounds (ten times the largest measured magnitude) counts as a miss of 100 variances per
// remaining sample. The whole model must then
// free-run the training record (every state integrated) without leaving the bounds, and if it
// does not, one state at a time is moved to its next best candidate until it does (at most 20
// tries).
#pragma once

#include <string>
#include <vector>

#include "methods/gp/search.h"
#include "methods/gp/segment_simulator.h"

namespace usvid::gp {

struct StateCandidates {
  std::string state;  // one of `names`
  std::vector<Model> models;
};

struct ScoredCandidate {
  size_t index = 0;    // into StateCandidates::models
  double score = 0.0;  // short-horizon error, the other states as measured
};

struct Selection {
  std::vector<size_t> chosen;           // per state, into its models
  std::vector<double> scores;           // per state, the chosen one's short-horizon error
  std::vector<double> standard_errors;  // per state, of the smallest error
  bool free_run_diverged = false;       // even the last one tried diverged on the training record
  int candidates_scored = 0;
  int rejected_for_divergence = 0;  // combinations that diverged before the chosen one
  std::vector<std::vector<ScoredCandidate>> candidate_scores;  // per state: each candidate's score
};

// Throws InputError when a state is not among the variables or the validation part is shorter
// than two samples.
Selection SelectModels(const SelectionData& data, const std::vector<StateCandidates>& states);

}  // namespace usvid::gp
