#include "methods/gp/search.h"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <sstream>

#include "core/error.h"
#include "core/parse_number.h"
#include "methods/gp/interpreter.h"
#include "methods/gp/ols.h"
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

// Evaluates, prunes and scores one tree.
template <typename T>
Model Score(const Tree& tree, const Columns<T>& data, Interpreter<T>& interp,
            const GpOptions& opt) {
  Model m;
  const std::vector<int> terms = SplitTerms(tree);
  NormalEquations eq(static_cast<int>(terms.size()));
  Eigen::MatrixXd x(Interpreter<T>::kBatch, static_cast<Eigen::Index>(terms.size()));
  for (long begin = 0; begin < data.rows; begin += Interpreter<T>::kBatch) {
    const int count = static_cast<int>(std::min<long>(Interpreter<T>::kBatch, data.rows - begin));
    interp.Evaluate(tree, begin, count);
    for (size_t t = 0; t < terms.size(); ++t) {
      const T* col = interp.Column(terms[t]);
      for (int r = 0; r < count; ++r) x(r, static_cast<Eigen::Index>(t)) = col[r];
    }
    eq.Add(x.topRows(count), Eigen::Map<const Eigen::VectorXd>(data.target.data() + begin, count));
  }
  const OlsFit fit = FitOls(eq, opt.ols_threshold);
  if (!fit.valid) {
    m.tree = tree;
    m.fitness = -1.0;  // worst, and finite
    return m;
  }
  std::vector<int> kept_roots;
  for (int k : fit.kept) kept_roots.push_back(terms[k]);
  m.tree = kept_roots.size() == terms.size() ? tree : SumOfTerms(tree, kept_roots);
  m.term_roots = SplitTerms(m.tree);
  m.weights = fit.weights;
  m.bias = fit.bias;
  m.r2 = fit.r2;
  m.mse = fit.mse;
  m.fitness =
      opt.fitness_mse ? -fit.mse : fit.r2 - opt.parsimony * static_cast<double>(m.tree.size());
  if (!std::isfinite(m.fitness)) m.fitness = -1.0;
  return m;
}

std::vector<long> SpreadRows(long total, long wanted) {
  std::vector<long> index;
  const long n = wanted > 0 ? std::min(total, wanted) : total;
  for (long i = 0; i < n; ++i) index.push_back(i * total / n);
  return index;
}

void UpdatePareto(std::vector<ParetoPoint>& front, const Model& m,
                  const std::vector<std::string>& names) {
  for (const ParetoPoint& p : front)
    if (p.size <= m.Size() && p.mse <= m.mse) return;  // dominated or equal
  std::erase_if(front, [&](const ParetoPoint& p) { return m.Size() <= p.size && m.mse <= p.mse; });
  front.push_back({m.Size(), m.mse, m.Equation(names)});
  std::sort(front.begin(), front.end(),
            [](const ParetoPoint& a, const ParetoPoint& b) { return a.size < b.size; });
}

template <typename T>
GpResult Run(const GpProblem& p, const GpOptions& opt,
             const std::function<void(const GenerationLog&)>& progress) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  const Columns<T> data(p, SpreadRows(p.target.size(), opt.fit_rows));
  PrimitiveSet set{opt.functions, static_cast<int>(p.names.size()), opt.constant_probability};
  const int n = opt.population;
  if (opt.threads > 0) omp_set_num_threads(opt.threads);

  GpResult result;
  std::vector<Model> population(n), next(n);
  // Generation 0: ramped half-and-half over depths 2..max_depth.
  auto breed = [&](int generation, int i, const std::vector<Model>& parents) {
    Rng rng = StreamFor(opt.seed, static_cast<uint64_t>(generation), static_cast<uint64_t>(i));
    if (generation == 0) {
      const int depth = 2 + i % std::max(1, opt.max_depth - 1);
      return RandomTree(rng, set, depth, i % 2 == 0);
    }
    auto tournament = [&]() -> const Model& {
      int best = static_cast<int>(rng() % n);
      for (int k = 1; k < opt.tournament; ++k) {
        const int c = static_cast<int>(rng() % n);
        if (parents[c].fitness > parents[best].fitness) best = c;
      }
      return parents[best];
    };
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    Tree child = tournament().tree;
    if (unit(rng) < opt.crossover) child = Crossover(rng, child, tournament().tree, opt.max_depth);
    if (unit(rng) < opt.mutation) child = Mutate(rng, child, set, opt.max_depth);
    return child;
  };

  double best_fitness = -INFINITY;
  int since_improvement = 0;
  for (int g = 0; g < opt.generations; ++g) {
    const auto gen_start = Clock::now();
    double nodes = 0.0;
#pragma omp parallel reduction(+ : nodes)
    {
      Interpreter<T> interp(data.Pointers());
#pragma omp for schedule(dynamic, 16)
      for (int i = 0; i < n; ++i) {
        if (g > 0 && i < opt.elites) {
          next[i] = population[i];  // the best, sorted first below
          continue;
        }
        const Tree tree = breed(g, i, population);
        next[i] = Score(tree, data, interp, opt);
        nodes += static_cast<double>(tree.size()) * static_cast<double>(data.rows);
      }
    }
    std::swap(population, next);
    // Stable order by fitness (ties by index): the same at any thread count.
    std::vector<int> order(n);
    for (int i = 0; i < n; ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return population[a].fitness > population[b].fitness; });
    std::vector<Model> sorted(n);
    for (int i = 0; i < n; ++i) sorted[i] = population[order[i]];
    population.swap(sorted);

    const double seconds = std::chrono::duration<double>(Clock::now() - gen_start).count();
    GenerationLog log{g,
                      population[0].fitness,
                      population[0].r2,
                      population[0].Size(),
                      0.0,
                      seconds > 0 ? nodes / seconds : 0.0};
    for (const Model& m : population) log.mean_size += static_cast<double>(m.Size()) / n;
    result.log.push_back(log);
    result.node_evaluations += nodes;
    result.evaluations += g == 0 ? n : n - opt.elites;
    for (int i = 0; i < std::min(n, 50); ++i) UpdatePareto(result.pareto, population[i], p.names);
    if (progress) progress(log);

    if (population[0].fitness > best_fitness + 1e-12) {
      best_fitness = population[0].fitness;
      since_improvement = 0;
    } else if (++since_improvement >= opt.stagnation) {
      result.stop_reason = "no improvement for " + std::to_string(opt.stagnation) + " generations";
      break;
    }
    if (population[0].r2 > 1.0 - 1e-12) {
      result.stop_reason = "exact fit";
      break;
    }
  }
  if (result.stop_reason.empty()) result.stop_reason = "generation limit";
  result.best = FitTree(population[0].tree, p, opt.ols_threshold);
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

Model FitTree(const Tree& tree, const GpProblem& problem, double ols_threshold) {
  const Columns<double> data(problem, SpreadRows(problem.target.size(), 0));
  Interpreter<double> interp(data.Pointers());
  GpOptions opt;
  opt.ols_threshold = ols_threshold;
  return Score(tree, data, interp, opt);
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

GpResult RunGp(const GpProblem& problem, const GpOptions& options,
               const std::function<void(const GenerationLog&)>& progress) {
  if (problem.names.empty() || problem.variables.size() != problem.names.size() ||
      problem.target.size() < 10)
    throw InputError("gp: needs named variables and at least 10 rows");
  if (options.population < 4 || options.generations < 1 || options.max_depth < 2)
    throw InputError("gp: population >= 4, generations >= 1 and max depth >= 2");
  return options.single_precision ? Run<float>(problem, options, progress)
                                  : Run<double>(problem, options, progress);
}

}  // namespace usvid::gp
