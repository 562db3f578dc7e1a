#include "methods/gp/grey_box.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

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
      out.push_back(Effect{
          EffectKind::kMissingTerm, {{"coefficient", coefficient}}, {}, state, std::move(term)});
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
    const int i = n >= size ? k
                  : n == 1  ? size - 1
                            : static_cast<int>(std::lround(k * (size - 1.0) / (n - 1.0)));
    if (out.empty() || out.back() != &front[i]) out.push_back(&front[i]);
  }
  return out;
}

struct Candidate {
  std::string state;
  Model model;
};

// What the three steps share: the vessel, its states and inputs, the search's variables.
struct GreyBoxFit {
  const VesselRef& vessel;
  const std::vector<double>& params;
  std::vector<std::string> states, inputs;
  GpProblem problem;  // the variables of the first parts
};

// 2. Each state's front of corrections, searched on the first parts' residual.
std::vector<Candidate> SearchFronts(GreyBoxFit& fit, const Dataset& first_parts,
                                    const GreyBoxOptions& options, GreyBoxResult& result) {
  const PreparedData first = Preprocess(first_parts, fit.states, fit.inputs, PreprocessOptions{});
  const std::map<std::string, Eigen::VectorXd> residual =
      DerivativeResidual(fit.vessel, first.data, fit.params);
  fit.problem = Variables(first.data, fit.states, fit.inputs, options.features);
  std::vector<Candidate> candidates;
  for (size_t k = 0; k < fit.states.size(); ++k) {
    fit.problem.target = residual.at(fit.states[k]);
    GpOptions search = options.search;
    search.seed = options.search.seed + 1000 * k;  // each state its own stream
    const GpResult gp = RunGp(fit.problem, search);
    result.node_evaluations += gp.node_evaluations;
    for (const ParetoPoint* p : Spread(gp.pareto, options.candidates_per_state))
      candidates.push_back({fit.states[k], p->model});
  }
  return candidates;
}

// 3. Forward selection, a state at a time, by the held-out parts' free runs: the corrections
// kept, in order, each with the error after it; `alone` gets each candidate's error as the
// vessel's only correction.
struct ForwardSelection {
  std::vector<const Candidate*> kept;
  std::vector<double> errors;
  std::vector<double> alone;
  double alone_bound = 0.0;  // above it, an error in `alone` is a lower bound
};

ForwardSelection SelectForward(const GreyBoxFit& fit, const Dataset& heldout,
                               const std::vector<Candidate>& candidates,
                               const GreyBoxOptions& options, GreyBoxResult& result) {
  ForwardSelection out;
  std::vector<Effect> kept_terms;
  std::set<std::string> corrected;
  hybrid::HeldoutFreeRun base =
      hybrid::HeldoutFreeRuns(fit.vessel, heldout, fit.params, {}, fit.states);
  double error = base.error;
  result.vessel_free_run_error = error;
  for (int round = 0; round < static_cast<int>(fit.states.size()); ++round) {
    // What a candidate's error can matter up to: to be kept, within the parsimony of an error
    // low enough to keep; in the first round also below the vessel's own, the alternatives the
    // closed-loop choice replays (metrics/closed_loop_choice.h). A free run is stopped once its
    // error is sure to exceed this, and its error is then a lower bound.
    const double keepable = (1.0 + options.parsimony) * (1.0 - options.min_gain) * error;
    const double matters = round == 0 ? std::max(error, keepable) : keepable;
    std::vector<double> errors(candidates.size(), kDiverged);
    std::vector<hybrid::HeldoutFreeRun> runs(candidates.size());
    ParallelFor(static_cast<int>(candidates.size()), options.search.threads, [&](int i) {
      if (corrected.contains(candidates[i].state)) return;
      std::vector<Effect> terms = kept_terms;
      for (Effect& e : AsEffects(candidates[i].model, fit.problem.names, candidates[i].state))
        terms.push_back(std::move(e));
      try {
        // The records the model of the round's start found hardest run first: a candidate
        // worse than `matters` is mostly worse there too, and is stopped sooner.
        runs[i] = hybrid::HeldoutFreeRuns(fit.vessel, heldout, fit.params, terms, fit.states,
                                          matters, base.per_record);
        errors[i] = runs[i].error;
      } catch (const std::exception&) {
        // A term the vessel cannot evaluate is not chosen (its error stays infinite).
      }
    });
    if (round == 0) {
      out.alone = errors;
      out.alone_bound = matters;
    }
    int lowest = -1;
    for (size_t i = 0; i < candidates.size(); ++i) {
      if (corrected.contains(candidates[i].state)) continue;
      result.tried.push_back({candidates[i].state, candidates[i].model.Equation(fit.problem.names),
                              errors[i], round, std::isfinite(errors[i]) && errors[i] > matters});
      if (lowest < 0 || errors[i] < errors[lowest]) lowest = static_cast<int>(i);
    }
    if (lowest < 0 || !(errors[lowest] <= (1.0 - options.min_gain) * error)) break;
    int best = lowest;
    for (size_t i = 0; i < candidates.size(); ++i)
      if (!corrected.contains(candidates[i].state) &&
          errors[i] <= (1.0 + options.parsimony) * errors[lowest] &&
          candidates[i].model.Size() < candidates[best].model.Size())
        best = static_cast<int>(i);
    const Candidate& c = candidates[best];
    corrected.insert(c.state);
    out.kept.push_back(&c);
    for (Effect& e : AsEffects(c.model, fit.problem.names, c.state))
      kept_terms.push_back(std::move(e));
    error = errors[best];
    base = std::move(runs[best]);  // kept, so run to the end: every record's share is known
    out.errors.push_back(error);
  }
  result.free_run_error = error;
  return out;
}

// 4. The weights on every row: of the kept corrections, and of each alternative.
void RefitOnEveryRow(const GreyBoxFit& fit, const Dataset& data,
                     const std::vector<Candidate>& candidates, const ForwardSelection& selection,
                     const GreyBoxOptions& options, GreyBoxResult& result) {
  const PreparedData all = Preprocess(data, fit.states, fit.inputs, PreprocessOptions{});
  const std::map<std::string, Eigen::VectorXd> residual =
      DerivativeResidual(fit.vessel, all.data, fit.params);
  GpProblem whole = Variables(all.data, fit.states, fit.inputs, options.features);
  const auto refitted = [&](const std::vector<const Candidate*>& corrections, double error) {
    GreyBoxAlternative a{"", {}, {}, error, false};
    for (const Candidate* c : corrections) {
      whole.target = residual.at(c->state);
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
  for (size_t i = 0; i < candidates.size(); ++i) {
    result.alternatives.push_back(refitted({&candidates[i]}, selection.alone[i]));
    result.alternatives.back().free_run_error_at_least =
        std::isfinite(selection.alone[i]) && selection.alone[i] > selection.alone_bound;
  }
  std::vector<const Candidate*> path;
  for (size_t k = 0; k < selection.kept.size(); ++k) {
    path.push_back(selection.kept[k]);
    if (path.size() > 1) result.alternatives.push_back(refitted(path, selection.errors[k]));
  }
  const GreyBoxAlternative kept = refitted(selection.kept, result.free_run_error);
  result.terms = kept.terms;
  result.corrections = kept.corrections;
}

}  // namespace

GreyBoxResult IdentifyGreyBox(const VesselRef& vessel, const std::vector<double>& params,
                              const Dataset& data, const GreyBoxOptions& options) {
  if (!(options.heldout > 0.0 && options.heldout < 1.0))
    throw InputError("gp --base: the held-out share must be in (0, 1)");
  const VesselInfo& info = vessel.Info();
  GreyBoxFit fit{vessel, params, DynamicStates(info, data), info.InputsIn(data), {}};
  // 1. Each record's first part fits, its last part judges.
  const RecordSplit parts = SplitEachRecord(data, options.heldout, 16, "gp --base");
  GreyBoxResult result;
  const std::vector<Candidate> candidates = SearchFronts(fit, parts.first, options, result);
  const ForwardSelection selection = SelectForward(fit, parts.last, candidates, options, result);
  RefitOnEveryRow(fit, data, candidates, selection, options, result);
  return result;
}

}  // namespace usvid::gp
