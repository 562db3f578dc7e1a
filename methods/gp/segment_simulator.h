// Simulates GP's equations over segments of a record, side by side: each segment starts from
// the measured value of the integrated states, is integrated by RK4 under the measured inputs
// (zero-order hold) and the measured values of every other variable, and is compared with the
// measured states at every sample. Model selection (model_selection.h) scores candidates with
// it and the simulation-error refit (simulation_refit.h) fits weights by it.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/expression.h"
#include "methods/gp/search.h"

namespace usvid::gp {

// A variable computed from others (a regime feature): recomputed in every simulation step from
// the simulated states and the measured rest.
struct DerivedColumn {
  int index = 0;               // into SelectionData::names
  Expression expression;       // of the variables `arguments`
  std::vector<int> arguments;  // into names, in the order of expression.Variables()
};

struct SelectionData {
  Eigen::VectorXd t;
  std::vector<std::string> names;          // variables, as in the search
  std::vector<Eigen::VectorXd> variables;  // every row
  long validation_begin = 0;               // the rows [validation_begin, end) score candidates
  double horizon_s = 10.0;
  std::vector<DerivedColumn> derived;  // computed after the states, in this order
};

// Integrates segments side by side: segment j starts at row starts[j] and runs `steps` samples.
// Each state's error is divided by its variance over the rows [validation_begin, end), and a
// state that leaves its bounds (ten times its largest measured magnitude) ends its segment.
class SegmentSimulator {
 public:
  // Segment starts every `steps` rows from `first`, each segment ending before row `end` and
  // inside one stretch of `t` between gaps (core/stretches.h): the segments restart after a gap.
  static std::vector<long> Starts(const Eigen::VectorXd& t, long first, long end, long steps);

  // Variances per sample charged to a segment for each sample after it left the bounds.
  static constexpr double kDivergedPenalty = 100.0;

  // `state_vars`: the variables integrated; the others are read from the data.
  SegmentSimulator(const SelectionData& data, const std::vector<int>& state_vars);

  // The mean over segments, steps and states of the squared error over the state's variance;
  // `diverged` says whether any segment left the bounds. `per_segment` (when given) receives
  // each segment's mean; `residuals` (when given) each segment's, step's and state's error over
  // the state's standard deviation, segment-major (0 after a segment left the bounds).
  double Error(const std::vector<const Model*>& models, const std::vector<long>& starts, long steps,
               bool& diverged, std::vector<double>* per_segment = nullptr,
               std::vector<double>* residuals = nullptr) const;

  // The whole record free-run, each stretch between gaps from its first row: the stretches'
  // Error, weighted by their steps.
  double FreeRunError(const std::vector<const Model*>& models, bool& diverged) const;

 private:
  // For each variable, whether `models` read it (directly or through a derived column).
  std::vector<bool> Read(const std::vector<const Model*>& models) const;
  // The columns the models read, at step k of the segments starting at starts[0..count): each
  // state's from `state` (a column per segment), the other variables' from the data, then the
  // derived columns from those (`args`: a buffer of one pointer per variable).
  void FillColumns(const std::vector<bool>& read, const Eigen::ArrayXXd& state, const long* starts,
                   long k, std::vector<std::vector<double>>& cols,
                   std::vector<const double*>& args) const;

  const SelectionData& data_;
  std::vector<int> state_vars_;
  std::vector<int> is_state_;
  std::vector<double> variance_, bound_;
};

}  // namespace usvid::gp
