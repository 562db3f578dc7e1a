// One GP-OLS search: a population of trees evolved to explain one target (a state's
// derivative) from named variables. Every individual is scored after GP-OLS pruning (ols.h);
// fitness is r^2 minus parsimony x size (the default), or minus the MSE. Tournament selection,
// elitism, crossover with probability p_c, mutation with p_m, and an early stop when the best
// fitness has not improved for `stagnation` generations or the fit is exact. Offspring i of
// generation g draws from its own stream StreamFor(seed, g, i), and OpenMP only divides the
// offspring among threads, so the result is the same at any thread count.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

#include "methods/gp/tree.h"

namespace usvid::gp {

struct GpOptions {
  // The reference report's Table 3.1: crossover 0.9, mutation 0.1, population 2000,
  // OLS threshold 0.05, max depth 6.
  int population = 2000;
  int generations = 50;
  int max_depth = 6;
  double crossover = 0.9;
  double mutation = 0.1;
  double ols_threshold = 0.05;
  int tournament = 5;
  int elites = 2;
  int stagnation = 10;
  std::vector<Op> functions = {Op::kAdd, Op::kSub, Op::kMul};
  double constant_probability = 0.1;
  bool fitness_mse = false;  // false: r^2 - parsimony * nodes
  double parsimony = 1e-4;
  long fit_rows = 4000;          // rows the search scores on (evenly spread); all for the refit
  bool single_precision = true;  // evaluate the search in float (the refit is double)
  uint64_t seed = 1;
  int threads = 0;  // 0: OpenMP's default
};

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
  double mse = 0.0;
  double fitness = -1.0;

  // "bias + w1*term1 + ..." in the contract's syntax.
  std::string Equation(const std::vector<std::string>& names) const;
  size_t Size() const { return tree.size(); }
};

struct ParetoPoint {
  size_t size = 0;
  double mse = 0.0;
  std::string equation;
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
};

// progress(log) after each generation (may be empty). Throws InputError on an empty problem.
GpResult RunGp(const GpProblem& problem, const GpOptions& options,
               const std::function<void(const GenerationLog&)>& progress = {});

// Scores one tree on all rows in double precision, with OLS pruning.
Model FitTree(const Tree& tree, const GpProblem& problem, double ols_threshold);

// The model's value bias + sum w_i term_i at every row of the variables (in `names` order).
Eigen::VectorXd Predict(const Model& model, const std::vector<Eigen::VectorXd>& variables);

}  // namespace usvid::gp
