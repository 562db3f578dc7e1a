#include "methods/gp/search.h"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <sstream>
#include <unordered_map>

#include "core/error.h"
#include "core/evenly_spread.h"
#include "core/parse_number.h"
#include "methods/gp/constant_fit.h"
#include "methods/gp/interpreter.h"
#include "methods/gp/ols.h"
#include "methods/gp/score_cache.h"
#include "methods/gp/term_selection.h"
#include "methods/gp/variation.h"

namespace usvid::gp {
namespace {

// The variables and target as column arrays of T, over the chosen rows.
template <typename T>
struct Columns {
  std::vector<std::vector<T>> vars;
  std::vector<double> target;
  long rows = 0;

  Columns(const GpProblem& p, const std::vector<long>& index)
      : rows(static_cast<long>(index.size())) {
    for (const Eigen::VectorXd& v : p.variables) {
      vars.emplace_back(index.size());
      for (size_t r = 0; r < index.size(); ++r) vars.back()[r] = static_cast<T>(v(index[r]));
    }
    target.resize(index.size());
    for (size_t r = 0; r < index.size(); ++r) target[r] = p.target(index[r]);
  }
  std::vector<const T*> Pointers() const {
    std::vector<const T*> out;
    for (const auto& v : vars) out.push_back(v.data());
    return out;
  }
};

// Evaluates, prunes and scores one tree. The rows' normal equations are kept per contiguous
// block for the held-out term selection, or summed for the threshold.
template <typename T>
Model Score(const Tree& tree, const Columns<T>& data, Interpreter<T>& interp,
            const GpOptions& opt) {
  Model m;
  const std::vector<int> terms = SplitTerms(tree);
  const int k = static_cast<int>(terms.size());
  const long blocks = opt.ols_threshold ? 1 : std::min<long>(kHeldOutBlocks, data.rows);
  std::vector<NormalEquations> eq(static_cast<size_t>(blocks), NormalEquations(k));
  auto block_start = [&](long b) { return b * data.rows / blocks; };
  Eigen::MatrixXd x(Interpreter<T>::kBatch, k);
  long block = 0;
  for (long begin = 0; begin < data.rows; begin += Interpreter<T>::kBatch) {
    const int count = static_cast<int>(std::min<long>(Interpreter<T>::kBatch, data.rows - begin));
    interp.Evaluate(tree, begin, count);
    for (int t = 0; t < k; ++t) {
      const T* col = interp.Column(terms[t]);
      for (int r = 0; r < count; ++r) x(r, t) = col[r];
    }
    for (long row = begin; row < begin + count;) {
      while (block + 1 < blocks && block_start(block + 1) <= row) ++block;
      const long end =
          block + 1 < blocks ? std::min(begin + count, block_start(block + 1)) : begin + count;
      eq[block].Add(x.middleRows(row - begin, end - row),
                    Eigen::Map<const Eigen::VectorXd>(data.target.data() + row, end - row));
      row = end;
    }
  }
  const OlsFit fit = opt.ols_threshold ? FitOls(eq[0], *opt.ols_threshold) : FitOlsHeldOut(eq);
  if (!fit.valid) {
    m.tree = tree;
    m.fitness = -1.0;  // worst, and finite
    return m;
  }
  std::vector<int> kept_roots;
  for (int kept : fit.kept) kept_roots.push_back(terms[kept]);
  m.tree = kept_roots.size() == terms.size() ? tree : SumOfTerms(tree, kept_roots);
  m.term_roots = SplitTerms(m.tree);
  m.weights = fit.weights;
  m.bias = fit.bias;
  m.r2 = fit.r2;
  m.r2_heldout = fit.r2_heldout;
  m.mse = fit.mse;
  m.fitness = opt.fitness_mse ? -fit.mse
                              : fit.r2_heldout - opt.parsimony * static_cast<double>(m.tree.size());
  if (!std::isfinite(m.fitness)) m.fitness = -1.0;
  return m;
}

// The front of held-out error (1 - r2_heldout) against size.
void UpdatePareto(std::vector<ParetoPoint>& front, const Model& m,
                  const std::vector<std::string>& names) {
  const double error = 1.0 - m.r2_heldout;
  for (const ParetoPoint& p : front)
    if (p.size <= m.Size() && 1.0 - p.r2_heldout <= error) return;  // dominated or equal
  std::erase_if(front, [&](const ParetoPoint& p) {
    return m.Size() <= p.size && error <= 1.0 - p.r2_heldout;
  });
  front.push_back({m.Size(), m.mse, m.r2_heldout, m.Equation(names), m});
  std::sort(front.begin(), front.end(),
            [](const ParetoPoint& a, const ParetoPoint& b) { return a.size < b.size; });
}

// The population sorted by fitness, stably (ties by index): the same at any thread count.
void SortByFitness(std::vector<Model>& population) {
  std::stable_sort(population.begin(), population.end(),
                   [](const Model& a, const Model& b) { return a.fitness > b.fitness; });
}

// Tournament selection: the fittest of opt.tournament individuals drawn at random.
const Model& Tournament(Rng& rng, const std::vector<Model>& parents, const GpOptions& opt) {
  const int n = static_cast<int>(parents.size());
  int best = static_cast<int>(rng() % n);
  for (int k = 1; k < opt.tournament; ++k) {
    const int c = static_cast<int>(rng() % n);
    if (parents[c].fitness > parents[best].fitness) best = c;
  }
  return parents[best];
}

// Offspring i of a generation, from its own random stream. `fresh`: ramped half-and-half over
// depths 2..max_depth (generation 0 and restarts); else a tournament winner, crossed over and
// mutated with the options' probabilities.
Tree Breed(const GpOptions& opt, const PrimitiveSet& set, int generation, int i, bool fresh,
           const std::vector<Model>& parents) {
  Rng rng = StreamFor(opt.seed, static_cast<uint64_t>(generation), static_cast<uint64_t>(i));
  if (fresh) {
    const int depth = 2 + i % std::max(1, opt.max_depth - 1);
    return RandomTree(rng, set, depth, i % 2 == 0);
  }
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Tree child = Tournament(rng, parents, opt).tree;
  if (unit(rng) < opt.crossover) {
    child = opt.term_mutation && rng() % 2 == 0
                ? CrossoverTerms(rng, child, Tournament(rng, parents, opt).tree, opt.max_depth)
                : Crossover(rng, child, Tournament(rng, parents, opt).tree, opt.max_depth);
  }
  if (unit(rng) < opt.mutation) {
    child = opt.term_mutation && rng() % 3 == 0 ? MutateTerm(rng, child, set, opt.max_depth)
                                                : Mutate(rng, child, set, opt.max_depth);
  }
  return child;
}

// How many generations a scored tree stays in the cache without being bred again. Most repeats
// are of the parents' generation; 3 keeps the cache to a few thousand trees.
constexpr int kCacheGenerations = 3;

// Generation g bred from `population` and scored into `next` (after the first, the elites
// carried over unchanged); returns the tree nodes evaluated. Each offspring is bred in
// parallel; a tree already scored in a recent generation, or earlier in this one, takes that
// score from `cache` (score_cache.h), and only the others are scored, again in parallel.
template <typename T>
double BreedAndScore(int g, bool fresh, const PrimitiveSet& set, const Columns<T>& data,
                     const GpOptions& opt, const std::vector<Model>& population, ScoreCache& cache,
                     std::vector<Model>& next) {
  const int n = opt.population;
  const int first = g > 0 ? opt.elites : 0;
  for (int i = 0; i < first; ++i) next[i] = population[i];  // the best, sorted first below
  std::vector<Tree> trees(static_cast<size_t>(n));
#pragma omp parallel for schedule(dynamic, 64)
  for (int i = first; i < n; ++i) trees[i] = Breed(opt, set, g, i, fresh, population);

  std::vector<int> to_score;
  std::vector<std::pair<int, int>> copies;  // (offspring, the earlier one with its tree)
  {
    std::unordered_map<Tree, int, ScoreCache::Hash, ScoreCache::Equal> first_of;
    for (int i = first; i < n; ++i) {
      if (const Model* known = cache.Find(trees[i], g)) {
        next[i] = *known;
      } else if (const auto [it, added] = first_of.try_emplace(trees[i], i); added) {
        to_score.push_back(i);
      } else {
        copies.emplace_back(i, it->second);
      }
    }
  }

  double nodes = 0.0;
  const int m = static_cast<int>(to_score.size());
#pragma omp parallel reduction(+ : nodes)
  {
    Interpreter<T> interp(data.Pointers());
#pragma omp for schedule(dynamic, 16)
    for (int j = 0; j < m; ++j) {
      const int i = to_score[j];
      next[i] = Score(trees[i], data, interp, opt);
      nodes += static_cast<double>(trees[i].size()) * static_cast<double>(data.rows);
    }
  }
  for (const int i : to_score) cache.Insert(trees[i], next[i], g);
  for (const auto& [i, j] : copies) next[i] = next[j];
  cache.Forget(g);
  return nodes;
}

// Levenberg-Marquardt on the constants of the best few not tuned yet (`exact`: the rows in
// double precision); a tuned tree replaces its parent when it scores better.
template <typename T>
void TuneElites(const Columns<T>& data, const Columns<double>& exact, const GpOptions& opt,
                std::vector<Model>& population) {
  const int n = opt.population;
  const std::vector<const double*> exact_columns = exact.Pointers();
  std::vector<int> chosen;
  for (int i = 0; i < n && static_cast<int>(chosen.size()) < opt.constant_elites; ++i)
    if (!population[i].constants_tuned) chosen.push_back(i);
#pragma omp parallel
  {
    Interpreter<T> interp(data.Pointers());
#pragma omp for schedule(dynamic, 1)
    for (size_t c = 0; c < chosen.size(); ++c) {
      Model& m = population[chosen[c]];
      m.constants_tuned = true;
      if (!HasTunableConstants(m)) continue;
      const ConstantFitResult fit =
          FitConstants(m, exact_columns, exact.target.data(), exact.rows, opt.constant_iterations);
      if (!fit.improved) continue;
      Model tuned = Score(fit.tree, data, interp, opt);
      tuned.constants_tuned = true;
      if (tuned.fitness > m.fitness) m = tuned;
    }
  }
  SortByFitness(population);
}

// Generation g's log line, of the sorted population.
GenerationLog LogGeneration(int g, const std::vector<Model>& population, double nodes,
                            double seconds) {
  const int n = static_cast<int>(population.size());
  GenerationLog log{g,
                    population[0].fitness,
                    population[0].r2,
                    population[0].Size(),
                    0.0,
                    seconds > 0 ? nodes / seconds : 0.0};
  for (const Model& m : population) log.mean_size += static_cast<double>(m.Size()) / n;
  return log;
}

// The best fitness so far and the generations since it last improved.
struct Stagnation {
  double best_fitness = -INFINITY;
  int since_improvement = 0;
};

// After a generation whose best is `best`: whether the search stops (its reason set in
// result.stop_reason). A search that stagnates restarts while it may: `fresh` is set, so that all
// but the elites are drawn anew in the next generation.
bool Stop(const Model& best, const GpOptions& opt, Stagnation& s, bool& fresh, GpResult& result) {
  if (best.r2 > 1.0 - 1e-12) {
    result.stop_reason = "exact fit";
    return true;
  }
  if (best.fitness > s.best_fitness + 1e-12) {
    s.best_fitness = best.fitness;
    s.since_improvement = 0;
  } else if (++s.since_improvement >= opt.stagnation) {
    if (result.restarts >= opt.restarts) {
      result.stop_reason =
          "no improvement for " + std::to_string(opt.stagnation) + " generations" +
          (opt.restarts > 0 ? " after " + std::to_string(result.restarts) + " restarts" : "");
      return true;
    }
    ++result.restarts;
    s.since_improvement = 0;
    fresh = true;
  }
  return false;
}

template <typename T>
GpResult Run(const GpProblem& p, const GpOptions& opt,
             const std::function<void(const GenerationLog&)>& progress) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  const std::vector<long> rows = EvenlySpread(p.target.size(), opt.fit_rows);
  const Columns<T> data(p, rows);
  const Columns<double> exact(p, rows);  // for the constant optimisation
  PrimitiveSet set{opt.functions, static_cast<int>(p.names.size()), opt.constant_probability};
  const int n = opt.population;
  if (opt.threads > 0) omp_set_num_threads(opt.threads);

  GpResult result;
  std::vector<Model> population(n), next(n);
  Stagnation stagnation;
  ScoreCache cache(kCacheGenerations);
  bool fresh = true;  // the next generation is drawn anew
  for (int g = 0; g < opt.generations; ++g) {
    const auto gen_start = Clock::now();
    const double nodes = BreedAndScore(g, fresh, set, data, opt, population, cache, next);
    fresh = false;
    std::swap(population, next);
    SortByFitness(population);
    if (opt.constant_iterations > 0 && opt.constant_elites > 0)
      TuneElites(data, exact, opt, population);

    const double seconds = std::chrono::duration<double>(Clock::now() - gen_start).count();
    const GenerationLog log = LogGeneration(g, population, nodes, seconds);
    result.log.push_back(log);
    result.node_evaluations += nodes;
    result.evaluations += g == 0 ? n : n - opt.elites;
    for (int i = 0; i < std::min(n, 50); ++i) UpdatePareto(result.pareto, population[i], p.names);
    if (progress) progress(log);
    if (Stop(population[0], opt, stagnation, fresh, result)) break;
  }
  if (result.stop_reason.empty()) result.stop_reason = "generation limit";
  result.best = FitTree(population[0].tree, p, opt);
  for (ParetoPoint& point : result.pareto) {
    point.model = FitTree(point.model.tree, p, opt);
    point.equation = point.model.Equation(p.names);
  }
  result.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return result;
}

}  // namespace

std::string Model::Equation(const std::vector<std::string>& names) const {
  std::ostringstream s;
  s << FormatNumber(bias);
  for (size_t t = 0; t < term_roots.size(); ++t) {
    const double w = weights[t];
    s << (w < 0 ? " - " : " + ") << FormatNumber(std::abs(w)) << "*"
      << ToString(tree, term_roots[t], names);
  }
  return s.str();
}

Model FitTree(const Tree& tree, const GpProblem& problem, const GpOptions& options) {
  const Columns<double> data(problem, EvenlySpread(problem.target.size(), 0));
  Interpreter<double> interp(data.Pointers());
  return Score(tree, data, interp, options);
}

Model FitTerms(const Tree& tree, const GpProblem& problem) {
  GpOptions every_term;
  every_term.ols_threshold = 0.0;  // no error reduction ratio is below 0
  return FitTree(tree, problem, every_term);
}

GpOptions ReportOptions() {
  GpOptions o;
  o.mutation = 0.1;
  o.ols_threshold = 0.05;
  o.restarts = 0;
  o.term_mutation = false;
  o.constant_iterations = 0;
  return o;
}

Eigen::VectorXd Predict(const Model& model, const std::vector<Eigen::VectorXd>& variables) {
  const Eigen::Index n = variables.empty() ? 0 : variables[0].size();
  std::vector<const double*> columns;
  for (const Eigen::VectorXd& v : variables) columns.push_back(v.data());
  Interpreter<double> interp(columns);
  Eigen::VectorXd out = Eigen::VectorXd::Constant(n, model.bias);
  for (Eigen::Index begin = 0; begin < n; begin += Interpreter<double>::kBatch) {
    const int count =
        static_cast<int>(std::min<Eigen::Index>(Interpreter<double>::kBatch, n - begin));
    interp.Evaluate(model.tree, begin, count);
    for (size_t t = 0; t < model.term_roots.size(); ++t) {
      const double* col = interp.Column(model.term_roots[t]);
      for (int r = 0; r < count; ++r) out(begin + r) += model.weights[t] * col[r];
    }
  }
  return out;
}

bool GpOptions::IsValid(std::string* error) const {
  auto fail = [error](const std::string& why) {
    *error = why;
    return false;
  };
  if (population < 4) return fail("population must be >= 4, got " + std::to_string(population));
  if (generations < 1)
    return fail("generations must be >= 1, got " + std::to_string(generations));
  if (max_depth < 2 || max_depth > 17)
    return fail("max_depth must be in [2, 17], got " + std::to_string(max_depth));
  if (ols_threshold && !(*ols_threshold >= 0 && *ols_threshold < 1))
    return fail("ols_threshold must be in [0, 1), got " + FormatNumber(*ols_threshold));
  if (restarts < 0) return fail("restarts must be >= 0, got " + std::to_string(restarts));
  if (constant_iterations < 0)
    return fail("constant_iterations must be >= 0 (0: no constant optimisation), got " +
                std::to_string(constant_iterations));
  if (constant_elites < 0)
    return fail("constant_elites must be >= 0, got " + std::to_string(constant_elites));
  if (fit_rows < 0) return fail("fit_rows must be >= 0 (0: every row), got " + std::to_string(fit_rows));
  return true;
}

GpResult RunGp(const GpProblem& problem, const GpOptions& options,
               const std::function<void(const GenerationLog&)>& progress) {
  if (problem.names.empty() || problem.variables.size() != problem.names.size() ||
      problem.target.size() < 10)
    throw InputError("gp: needs named variables and at least 10 rows");
  if (std::string error; !options.IsValid(&error)) throw InputError("gp: " + error);
  return options.single_precision ? Run<float>(problem, options, progress)
                                  : Run<double>(problem, options, progress);
}

}  // namespace usvid::gp
