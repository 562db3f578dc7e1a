#include "methods/gp/grey_box.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"
#include "core/expression.h"
#include "core/parallel_for.h"
#include "core/records.h"
#include "methods/hybrid/heldout_free_run.h"
#include "methods/refit/refit.h"
#include "preprocessing/pipeline.h"
#include "simulation/vessel_simulator.h"

namespace usvid::gp {
namespace {

constexpr double kDiverged = std::numeric_limits<double>::infinity();

// The vessel's dynamic states (no position or heading), each a column of `data`.
std::vector<std::string> DynamicStates(const VesselInfo& info, const Dataset& data) {
  std::vector<std::string> out;
  for (const std::string& s : info.states)
    if (!IsPositionOrHeading(s)) {
      if (!data.Has(s))
        throw InputError(data.SourcePrefix() + "gp --base " + info.name + " needs state column '" +
                         s + "'");
      out.push_back(s);
    }
  return out;
}

// The search's variables on `prepared`: the dynamic states, the inputs, then each feature (a
// column named by its expression in parentheses, computed from the others).
GpProblem Variables(const Dataset& prepared, const std::vector<std::string>& states,
                    const std::vector<std::string>& inputs,
                    const std::vector<DerivedVariable>& features) {
  GpProblem p;
  for (const auto& names : {states, inputs})
    for (const std::string& n : names) {
      p.names.push_back(n);
      p.variables.push_back(prepared[n]);
    }
  for (const DerivedVariable& f : features) {
    if (std::ranges::find(p.names, f.Column()) != p.names.end()) continue;
    p.names.push_back(f.Column());
    p.variables.push_back(Expression::Parse(f.expression, "feature " + f.name).Evaluate(prepared));
  }
  return p;
}

// The model's terms as the vessel's missing terms: the bias as the term "1", each term as
// written in the equation syntax (a feature's column name is its expression in parentheses).
std::vector<Effect> AsEffects(const Model& m, const std::vector<std::string>& names,
                              const std::string& state) {
  std::vector<Effect> out;
  const auto add = [&](double coefficient, std::string term) {
    if (coefficient != 0.0 && std::isfinite(coefficient))
      out.push_back(Effect{EffectKind::kMissingTerm, {{"coefficient", coefficient}}, {}, state,
                           std::move(term)});
  };
  add(m.bias, "1");
  for (size_t t = 0; t < m.term_roots.size(); ++t)
    add(m.weights[t], ToString(m.tree, m.term_roots[t], names));
  return out;
}

// Up to `n` points of a front (ordered by size), spread from the smallest to the largest.
std::vector<const ParetoPoint*> Spread(const std::vector<ParetoPoint>& front, int n) {
  std::vector<const ParetoPoint*> out;
  const int size = static_cast<int>(front.size());
  if (size == 0 || n <= 0) return out;
  for (int k = 0; k < std::min(n, size); ++k) {
    const int i = n >= size ? k : static_cast<int>(std::lround(k * (size - 1.0) / (n - 1.0)));
    if (out.empty() || out.back() != &front[i]) out.push_back(&front[i]);
  }
  return out;
}

struct Candidate {
  std::string state;
  Model model;
};

}  // namespace

GreyBoxResult IdentifyGreyBox(const std::string& vessel, const std::vector<double>& params,
                              const Dataset& data, const GreyBoxOptions& options) {
  if (!(options.heldout > 0.0 && options.heldout < 1.0))
    throw InputError("gp --base: the held-out share must be in (0, 1)");
  const VesselInfo& info = FindVessel(vessel).Info();
  const std::vector<std::string> states = DynamicStates(info, data);
  const std::vector<std::string> inputs = info.InputsIn(data);
  const RecordSplit parts = SplitEachRecord(data, options.heldout, 16, "gp --base");

  // 2. Each state's front of corrections, searched on the first part's residual.
  const PreparedData first = Preprocess(parts.first, states, inputs, PreprocessOptions{});
  const std::map<std::string, Eigen::VectorXd> residual =
      DerivativeResidual(vessel, first.data, params);
  GpProblem problem = Variables(first.data, states, inputs, options.features);
  GreyBoxResult result;
  std::vector<Candidate> candidates;
  for (size_t k = 0; k < states.size(); ++k) {
    problem.target = residual.at(states[k]);
    GpOptions search = options.search;
    search.seed = options.search.seed + 1000 * k;  // each state its own stream
    const GpResult gp = RunGp(problem, search);
    result.node_evaluations += gp.node_evaluations;
    for (const ParetoPoint* p : Spread(gp.pareto, options.candidates_per_state))
      candidates.push_back({states[k], p->model});
  }

  // 3. Forward selection, a state at a time, by the held-out part's free runs.
  std::vector<Effect> kept;
  std::map<std::string, const Candidate*> chosen;
  std::vector<const Candidate*> order;  // as kept
  std::vector<double> path_errors;      // the error after each
  std::vector<double> alone;            // each candidate's, the vessel's only correction
  double error = hybrid::HeldoutFreeRunError(vessel, parts.last, params, {}, states);
  result.vessel_free_run_error = error;
  for (int round = 0; round < static_cast<int>(states.size()); ++round) {
    std::vector<double> errors(candidates.size(), kDiverged);
    ParallelFor(static_cast<int>(candidates.size()), options.search.threads, [&](int i) {
      if (chosen.contains(candidates[i].state)) return;
      std::vector<Effect> terms = kept;
      for (Effect& e : AsEffects(candidates[i].model, problem.names, candidates[i].state))
        terms.push_back(std::move(e));
      try {
        errors[i] = hybrid::HeldoutFreeRunError(vessel, parts.last, params, terms, states);
      } catch (const std::exception&) {
        // A term the vessel cannot evaluate is not chosen (its error stays infinite).
      }
    });
    if (round == 0) alone = errors;
    int lowest = -1;
    for (size_t i = 0; i < candidates.size(); ++i) {
      if (chosen.contains(candidates[i].state)) continue;
      result.tried.push_back({candidates[i].state, candidates[i].model.Equation(problem.names),
                              errors[i], round});
      if (lowest < 0 || errors[i] < errors[lowest]) lowest = static_cast<int>(i);
    }
    if (lowest < 0 || !(errors[lowest] <= (1.0 - options.min_gain) * error)) break;
    int best = lowest;
    for (size_t i = 0; i < candidates.size(); ++i)
      if (!chosen.contains(candidates[i].state) &&
          errors[i] <= (1.0 + options.parsimony) * errors[lowest] &&
          candidates[i].model.Size() < candidates[best].model.Size())
        best = static_cast<int>(i);
    const Candidate& c = candidates[best];
    chosen[c.state] = &c;
    order.push_back(&c);
    path_errors.push_back(errors[best]);
    for (Effect& e : AsEffects(c.model, problem.names, c.state)) kept.push_back(std::move(e));
    error = errors[best];
  }
  result.free_run_error = error;

  // 4. The weights on every row: of the kept corrections, and of each alternative.
  const PreparedData all = Preprocess(data, states, inputs, PreprocessOptions{});
  const std::map<std::string, Eigen::VectorXd> all_residual =
      DerivativeResidual(vessel, all.data, params);
  GpProblem whole = Variables(all.data, states, inputs, options.features);
  const auto refitted = [&](const std::vector<const Candidate*>& corrections, double error) {
    GreyBoxAlternative a{"", {}, {}, error};
    for (const Candidate* c : corrections) {
      whole.target = all_residual.at(c->state);
      const Model m = FitTerms(c->model.tree, whole);
      a.label += (a.label.empty() ? "" : " + ") + c->state + " (size " +
                 std::to_string(c->model.Size()) + ")";
      a.corrections[c->state] = m.Equation(whole.names);
      for (Effect& e : AsEffects(m, whole.names, c->state)) a.terms.push_back(std::move(e));
    }
    if (a.label.empty()) a.label = "vessel";
    return a;
  };
  result.alternatives.push_back(refitted({}, result.vessel_free_run_error));
  for (size_t i = 0; i < candidates.size(); ++i)
    result.alternatives.push_back(refitted({&candidates[i]}, alone[i]));
  std::vector<const Candidate*> path;
  for (const Candidate* c : order) {
    path.push_back(c);
    if (path.size() > 1) result.alternatives.push_back(refitted(path, path_errors[path.size() - 1]));
  }
  const GreyBoxAlternative kept_model = refitted(order, result.free_run_error);
  result.terms = kept_model.terms;
  result.corrections = kept_model.corrections;
  return result;
}

}  // namespace usvid::gp
