// One GP-OLS search: a population of trees evolved to explain one target (a state's
// derivative) from named variables. Every individual is scored after GP-OLS pruning: by default
// the number of terms is chosen by held-out error over contiguous blocks (term_selection.h) and
// fitness is that held-out r^2 minus parsimony x size; with an `ols_threshold` (the report's
// GP-OLS, ols.h) terms under the threshold are cut and fitness is the training r^2 minus
// parsimony x size (or minus the MSE). Tournament selection, elitism, crossover with
// probability p_c (subtree crossover, and term crossover: a whole term of the second parent
// added to the first one's sum), mutation with p_m (subtree, point, and term mutation: a new
// small term added to the sum or put in place of one), constant optimisation of the elites
// (constant_fit.h),
// and on stagnation a restart: all but the elites drawn anew, up to `restarts` times, before
// the search stops. Offspring i of generation g draws from its own stream StreamFor(seed, g, i),
// and OpenMP only divides the offspring among threads, so the result is the same at any thread
// count.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "methods/gp/tree.h"

namespace usvid::gp {

struct GpOptions {
  int population = 2000;
  int generations = 50;
  int max_depth = 6;
  double crossover = 0.9;
  double mutation = 0.3;  // the report's 0.1 left 1 of 10 odin3dof seeds without |v| v
  // Unset: terms chosen by held-out error (term_selection.h). Set: the report's ERR threshold.
  std::optional<double> ols_threshold;
  int tournament = 5;
  int elites = 2;
  int stagnation = 10;
  int restarts = 2;             // restarts on stagnation before stopping
  bool term_mutation = true;    // term crossover and mutation (variation.h) besides subtree ones
  int constant_iterations = 5;  // Levenberg-Marquardt iterations per elite (0: none)
  int constant_elites = 4;      // how many of the best are tuned each generation
  std::vector<Op> functions = {Op::kAdd, Op::kSub, Op::kMul};
  double constant_probability = 0.1;
  bool fitness_mse = false;  // false: r^2 - parsimony * nodes
  double parsimony = 1e-4;
  long fit_rows = 4000;          // rows the search scores on (evenly spread); all for the refit
  bool single_precision = true;  // evaluate the search in float (the refit is double)
  uint64_t seed = 1;
  int threads = 0;  // 0: OpenMP's default

  // The one check of these options (Ceres's Solver::Options::IsValid): false, with `error`
  // naming the option and its rule, for population < 4, generations < 1, max_depth outside
  // [2, 17], ols_threshold outside [0, 1), or a negative restarts, constant_iterations,
  // constant_elites or fit_rows.
  bool IsValid(std::string* error) const;
};

// The reference report's Table 3.1 and nothing added: crossover 0.9, mutation 0.1, population
// 2000, OLS threshold 0.05, max depth 6, operators + - *; no term mutation, no constant
// optimisation, no restarts.
GpOptions ReportOptions();

struct GpProblem {
  std::vector<std::string> names;          // variables (channels)
  std::vector<Eigen::VectorXd> variables;  // one column per name
  Eigen::VectorXd target;
};

struct Model {
  Tree tree;                    // the sum of the terms
  std::vector<int> term_roots;  // in `tree`
  std::vector<double> weights;  // one per term
  double bias = 0.0;
  double r2 = 0.0;
  double r2_heldout = 0.0;  // r2 for a threshold fit
  double mse = 0.0;
  double fitness = -1.0;
  bool constants_tuned = false;

  // "bias + w1*term1 + ..." in the equation syntax (docs/data.md#equation-syntax).
  std::string Equation(const std::vector<std::string>& names) const;
  size_t Size() const { return tree.size(); }
};

// A point of the front of held-out error against size, with its model refitted on every row.
struct ParetoPoint {
  size_t size = 0;
  double mse = 0.0;
  double r2_heldout = 0.0;
  std::string equation;
  Model model;
};

struct GenerationLog {
  int generation = 0;
  double best_fitness = 0.0, best_r2 = 0.0;
  size_t best_size = 0;
  double mean_size = 0.0;
  double node_evals_per_second = 0.0;
};

struct GpResult {
  Model best;
  std::vector<ParetoPoint> pareto;  // by size, each smaller than the next in error
  std::vector<GenerationLog> log;
  long evaluations = 0;
  double node_evaluations = 0.0;
  double seconds = 0.0;
  std::string stop_reason;
  int restarts = 0;
};

// progress(log) after each generation (may be empty). Throws InputError on an empty problem.
GpResult RunGp(const GpProblem& problem, const GpOptions& options,
               const std::function<void(const GenerationLog&)>& progress = {});

// Scores one tree on all rows in double precision, with OLS pruning as `options` say.
Model FitTree(const Tree& tree, const GpProblem& problem, const GpOptions& options);

// Every term of `tree` weighted by least squares on all rows in double precision, none cut
// (but a term that depends linearly on those before it): the refit of a candidate whose terms
// are chosen already, as model_selection.h chooses them by simulation.
Model FitTerms(const Tree& tree, const GpProblem& problem);

// The model's value bias + sum w_i term_i at every row of the variables (in `names` order).
Eigen::VectorXd Predict(const Model& model, const std::vector<Eigen::VectorXd>& variables);

}  // namespace usvid::gp
