// Which of GP's candidate equations to return: chosen by how the whole model free-runs, not by
// equation error alone. An equation that fits derivatives to 0.1 % can still make a model that
// drifts or blows up once its own outputs feed back into it.
//
// Each state with an equation has candidates (its search's Pareto front of held-out error
// against size, and its best individual). A combination, one candidate per state, is scored by
// its short-horizon simulation error on the validation rows: from every `horizon_s`-th second
// the states with equations are integrated by RK4 from the measured values, over `horizon_s`,
// under the measured inputs (zero-order hold) and the measured values of variables that have no
// equation; the score is the sum over states of the mean squared error divided by the state's
// variance. A segment that leaves the bounds (ten times the largest measured magnitude) counts
// as a miss of 100 variances per remaining sample. The combination is found by coordinate
// descent (two passes over the states, each keeping the best candidate of one state given the
// others). Then it must free-run the whole record it was trained on without leaving the bounds;
// if it does not, the next best combination scored is tried.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "methods/gp/search.h"

namespace usvid::gp {

struct SelectionData {
  Eigen::VectorXd t;
  std::vector<std::string> names;          // variables, as in the search
  std::vector<Eigen::VectorXd> variables;  // every row
  long validation_begin = 0;               // the rows [validation_begin, end) score candidates
  double horizon_s = 10.0;
};

struct StateCandidates {
  std::string state;  // one of `names`
  std::vector<Model> models;
};

struct ScoredCandidate {
  size_t index = 0;  // into StateCandidates::models
  double score = 0.0;  // with the other states at their chosen candidates
};

struct Selection {
  std::vector<size_t> chosen;  // per state, into its models
  double score = 0.0;          // short-horizon error of the chosen combination
  bool free_run_diverged = false;  // even the chosen one diverged on the training record
  int combinations_scored = 0;
  int rejected_for_divergence = 0;
  std::vector<std::vector<ScoredCandidate>> last_pass;  // per state: each candidate's score
};

// Throws InputError when a state is not among the variables or the validation part is shorter
// than two samples.
Selection SelectModels(const SelectionData& data, const std::vector<StateCandidates>& states);

}  // namespace usvid::gp
