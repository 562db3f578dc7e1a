#include "methods/gp/gp_identify.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include "core/error.h"
#include "core/parse_number.h"
#include "core/stretches.h"
#include "methods/gp/astern_symmetry.h"
#include "methods/gp/model_selection.h"
#include "methods/gp/ols.h"
#include "methods/gp/simulation_refit.h"
#include "methods/gp/term_completion.h"
#include "methods/gp/tree.h"
#include "methods/gp/validation_split.h"
#include "methods/straight_running.h"

namespace usvid::gp {

std::vector<Op> ParseOperators(const std::string& list) {
  static const std::pair<const char*, Op> kKnown[] = {
      {"+", Op::kAdd},   {"-", Op::kSub},     {"*", Op::kMul},   {"/", Op::kDiv},
      {"abs", Op::kAbs}, {"tanh", Op::kTanh}, {"sin", Op::kSin}, {"cos", Op::kCos},
      {"exp", Op::kExp}, {"sqrt", Op::kSqrt}};
  std::vector<Op> ops;
  std::stringstream in(list);
  for (std::string item; std::getline(in, item, ',');) {
    bool found = false;
    for (const auto& [name, op] : kKnown)
      if (item == name) {
        if (std::find(ops.begin(), ops.end(), op) == ops.end()) ops.push_back(op);
        found = true;
      }
    if (!found)
      throw InputError("--operators: unknown operator '" + item +
                       "' (known: + - * / abs tanh sin cos exp sqrt)");
  }
  if (ops.empty()) throw InputError("--operators: the list is empty");
  return ops;
}

std::string OperatorList(const std::vector<Op>& ops) {
  std::string s;
  for (Op op : ops) s += (s.empty() ? "" : ",") + std::string(Symbol(op));
  return s;
}

namespace {

using StateProgress = std::function<void(const std::string&, const GenerationLog&)>;

// The first `rows` rows of every variable and of the target.
GpProblem Head(const GpProblem& p, long rows) {
  GpProblem out;
  out.names = p.names;
  for (const Eigen::VectorXd& v : p.variables) out.variables.push_back(v.head(rows));
  out.target = p.target.head(rows);
  return out;
}

nlohmann::json CandidateJson(const Model& m, const std::vector<std::string>& names) {
  return {{"size", m.Size()}, {"r2_heldout", m.r2_heldout}, {"equation", m.Equation(names)}};
}

// The measured variables the search draws from: `variables`, then `inputs`.
GpProblem MeasuredVariables(const PreparedData& prepared, const std::vector<std::string>& variables,
                            const std::vector<std::string>& inputs) {
  GpProblem all;
  for (const auto& names : {variables, inputs})
    for (const std::string& n : names) {
      all.names.push_back(n);
      all.variables.push_back(prepared.data[n]);
    }
  return all;
}

// The index of the variable `name` among `all`'s, or -1.
int Index(const GpProblem& all, const std::string& name) {
  const auto it = std::ranges::find(all.names, name);
  return it == all.names.end() ? -1 : static_cast<int>(it - all.names.begin());
}

// Appends each feature not yet among the variables, and its column of `derived`.
// A feature is named by its expression in parentheses, so that every equation written is in
// channel names, and is computed from the variables it names (which must be among them).
void AddFeatures(const std::vector<DerivedVariable>& features, const PreparedData& prepared,
                 GpProblem* all, std::vector<DerivedColumn>* derived) {
  for (const DerivedVariable& f : features) {
    if (Index(*all, f.Column()) >= 0) continue;
    DerivedColumn d{static_cast<int>(all->names.size()),
                    Expression::Parse(f.expression, "feature " + f.name),
                    {}};
    for (const std::string& arg : d.expression.Variables()) {
      const int index = Index(*all, arg);
      if (index < 0)
        throw InputError("gp: feature " + f.name + " = " + f.expression + " needs variable '" +
                         arg + "'");
      d.arguments.push_back(index);
    }
    all->names.push_back(f.Column());
    all->variables.push_back(d.expression.Evaluate(prepared.data));
    derived->push_back(std::move(d));
  }
}

// The rows searched on: all but the last fraction `f` (the validation part; of each stretch
// when the split says), or every row when f is 0. Throws InputError when either part is too
// short.
long TrainRows(long rows, double f, const ValidationSplit& split) {
  const long train_rows = split.reordered ? split.train_rows
                          : f > 0         ? std::lround((1.0 - f) * static_cast<double>(rows))
                                          : rows;
  if (f > 0 && (train_rows < 10 || rows - train_rows < 2))
    throw InputError("gp: --validation-fraction " + FormatNumber(f) + " leaves " +
                     std::to_string(train_rows) + " rows to search on and " +
                     std::to_string(rows - train_rows) + " to validate on (need 10 and 2)");
  return train_rows;
}

// One search per state on the training rows, its result appended to `results`. A state's
// candidates are the search's best and its Pareto front, each equation once.
std::vector<StateCandidates> SearchStates(const PreparedData& prepared,
                                          const std::vector<std::string>& states, long train_rows,
                                          const GpOptions& search, const StateProgress& progress,
                                          GpProblem* all, std::vector<GpResult>* results,
                                          double* node_evaluations) {
  std::vector<StateCandidates> candidates;
  for (const std::string& state : states) {
    all->target = prepared.data[state + "_dot"];
    results->push_back(RunGp(Head(*all, train_rows), search, [&](const GenerationLog& log) {
      if (progress) progress(state, log);
    }));
    const GpResult& r = results->back();
    *node_evaluations += r.node_evaluations;
    StateCandidates c{state, {r.best}};
    std::set<std::string> seen = {r.best.Equation(all->names)};
    for (const ParetoPoint& p : r.pareto)
      if (seen.insert(p.equation).second) c.models.push_back(p.model);
    candidates.push_back(std::move(c));
  }
  return candidates;
}

// Each candidate offered the completion library (term_completion.h) on the training rows; a
// completed model that fits and is a new equation becomes another candidate.
void CompleteCandidates(const PreparedData& prepared, const std::vector<std::string>& states,
                        const GpProblem& all, const std::vector<DerivedColumn>& derived,
                        long train_rows, const GpOptions& search,
                        std::vector<StateCandidates>* candidates) {
  std::vector<int> state_vars, feature_vars;
  for (const std::string& s : states)
    if (const int index = Index(all, s); index >= 0) state_vars.push_back(index);
  for (const DerivedColumn& d : derived) feature_vars.push_back(d.index);
  const std::vector<Tree> library = CompletionLibrary(state_vars, feature_vars, search.functions);
  const GpProblem head = Head(all, train_rows);
  for (size_t i = 0; i < states.size(); ++i) {
    GpProblem p = head;
    p.target = prepared.data[states[i] + "_dot"].head(train_rows);
    std::vector<Model>& models = (*candidates)[i].models;
    std::set<std::string> seen;
    for (const Model& m : models) seen.insert(m.Equation(all.names));
    const size_t n = models.size();
    for (size_t c = 0; c < n; ++c) {
      Model completed = CompleteTerms(models[c], library, p, search);
      if (completed.fitness > -1.0 && seen.insert(completed.Equation(all.names)).second)
        models.push_back(std::move(completed));
    }
  }
}

// Whether every state is a variable of its own (which its simulation needs).
bool AllAmong(const std::vector<std::string>& states, const std::vector<std::string>& names) {
  return std::all_of(states.begin(), states.end(), [&](const std::string& s) {
    return std::find(names.begin(), names.end(), s) != names.end();
  });
}

// The chosen terms of each state refitted on every row by equation error; with `surge` >= 0
// their damping first written with |u| (astern_symmetry.h), the states so changed appended to
// `symmetric`. With `keep_terms` (a candidate chosen by simulation) every term stays: the term
// selection, run again on every row, could cut a term the simulation chose it for, such as
// the only linear damping of a yaw whose other damping vanishes with the drift. Without it (the
// search's best, unvalidated) the terms are selected again as the search did.
std::vector<Model> FitChosen(const PreparedData& prepared, const std::vector<std::string>& states,
                             const std::vector<StateCandidates>& candidates,
                             const Selection& selection, const GpOptions& search, bool keep_terms,
                             int surge, GpProblem* all, std::vector<std::string>* symmetric) {
  std::vector<Model> bests;
  for (size_t i = 0; i < states.size(); ++i) {
    all->target = prepared.data[states[i] + "_dot"];
    const Model& chosen = candidates[i].models[selection.chosen[i]];
    Tree tree = chosen.tree;
    if (surge >= 0) {
      const size_t size = tree.size();
      tree = AsternSymmetric(tree, surge, Index(*all, states[i]));
      if (tree.size() != size) symmetric->push_back(states[i]);
    }
    if (!keep_terms) {
      bests.push_back(FitTree(tree, *all, search));
      continue;
    }
    Model best = FitTerms(tree, *all);
    best.r2_heldout = chosen.r2_heldout;  // on the search part's held-out blocks
    bests.push_back(std::move(best));
  }
  return bests;
}

// The variable index of the surge speed u when the chosen equations' damping is to be written
// with |u| (astern_symmetry.h): u is a state and goes below 0 on some row; otherwise -1.
int AsternSurge(const std::vector<std::string>& states, const GpProblem& all) {
  if (std::ranges::find(states, "u") == states.end()) return -1;
  const int u = Index(all, "u");
  if (u < 0 || !(all.variables[static_cast<size_t>(u)].array() < 0).any()) return -1;
  return u;
}

// The simulations' view of the variables, which it holds until the simulations are done and
// then gives back: on a long log a copy of every variable would be one of the largest blocks.
class LentVariables {
 public:
  LentVariables(const PreparedData& prepared, GpProblem* all, long validation_begin,
                double horizon_s, const std::vector<DerivedColumn>& derived)
      : all_(all),
        data_{prepared.data.t(), all->names, std::move(all->variables), validation_begin,
              horizon_s, derived} {}
  ~LentVariables() { all_->variables = std::move(data_.variables); }
  LentVariables(const LentVariables&) = delete;
  LentVariables& operator=(const LentVariables&) = delete;
  const SelectionData& data() const { return data_; }

 private:
  GpProblem* all_;
  SelectionData data_;
};

// The weights of `bests` refitted by simulation error (simulation_refit.h); every state must be
// among the variables.
SimulationRefit RefineBySimulation(const PreparedData& prepared,
                                   const std::vector<std::string>& states, GpProblem* all,
                                   const std::vector<DerivedColumn>& derived, long train_rows,
                                   double horizon_s, std::vector<Model>* bests) {
  std::vector<int> state_vars;
  for (const std::string& s : states) state_vars.push_back(Index(*all, s));
  const LentVariables lent(prepared, all, 0, horizon_s, derived);
  return RefitBySimulation(lent.data(), state_vars, *bests, {horizon_s, 30, train_rows});
}

// d(x')/dx of `model` for the state `var` at each row of `at`, by central differences of step h.
Eigen::VectorXd OwnSlope(const Model& model, int var, std::vector<Eigen::VectorXd> at, double h) {
  Eigen::VectorXd& x = at[static_cast<size_t>(var)];
  x.array() += h;
  const Eigen::VectorXd up = Predict(model, at);
  x.array() -= 2 * h;
  return (up - Predict(model, at)) / (2 * h);
}

// d(x')/dx of `model` for the state `var` at straight running (methods/straight_running.h), the
// derived variables (regime features, the rudder's inflow) recomputed from the point's channels.
double StraightRunningSlope(const Model& model, int var, const GpProblem& all,
                            const std::vector<DerivedColumn>& derived) {
  std::vector<ChannelLevel> levels;
  for (const Eigen::VectorXd& column : all.variables)
    levels.push_back(LevelOf(std::vector<double>(column.begin(), column.end())));
  const std::vector<std::vector<double>> points =
      StraightRunningPoints(all.names, levels, static_cast<size_t>(var));
  const Eigen::Index n = static_cast<Eigen::Index>(points.size());
  std::vector<Eigen::VectorXd> at(all.names.size(), Eigen::VectorXd(n));
  for (Eigen::Index p = 0; p < n; ++p) {
    for (size_t i = 0; i < at.size(); ++i) at[i](p) = points[static_cast<size_t>(p)][i];
    for (const DerivedColumn& d : derived) {
      std::vector<double> args;
      for (int a : d.arguments) args.push_back(at[static_cast<size_t>(a)](p));
      at[static_cast<size_t>(d.index)](p) = d.expression.Evaluate(args);
    }
  }
  const double h = 1e-6 * (std::abs(at[static_cast<size_t>(var)](0)) +
                           levels[static_cast<size_t>(var)].rms + 1e-12);
  return OwnSlope(model, var, std::move(at), h).mean();
}

// Whether `model` of the state `var` damps or restores its own state, by d(x')/dx (central
// differences) over the rows of `t`: below 0 on average over each stretch between gaps (each
// record of a joint fit; kUndamped), or at every row (kEveryRow), where an equation whose
// damping comes and goes with other states fails (v' = c r u |v| damps in one turn and drives
// in the other, or in reverse); and, by either rule, below 0 at straight running, where an
// equation damped only through another state is not (u' = c - k |v u|;
// methods/straight_running.h).
bool Damps(const Model& model, int var, const GpProblem& all,
           const std::vector<DerivedColumn>& derived, const Eigen::VectorXd& t, DampingOffer rule) {
  if (!(StraightRunningSlope(model, var, all, derived) < 0)) return false;
  const Eigen::VectorXd& x = all.variables[static_cast<size_t>(var)];
  const double h = 1e-6 * (std::sqrt(x.squaredNorm() / std::max<double>(1, x.size())) + 1e-12);
  const Eigen::VectorXd slope = OwnSlope(model, var, all.variables, h);
  if (rule == DampingOffer::kEveryRow) return (slope.array() < 0).all();
  for (const Stretch& s : Stretches(t, kGridGapFactor))
    if (!(slope.segment(s.first, s.rows()).mean() < 0)) return false;
  return true;
}

// `model` with the variable `var` added as one more term of weight 0.
Model WithTerm(Model model, int var) {
  model.tree.push_back({Op::kVar, static_cast<uint16_t>(var), 1, 0.0});
  model.tree.push_back({Op::kAdd, 0, 1, 0.0});
  UpdateLengths(model.tree);
  model.term_roots = SplitTerms(model.tree);
  model.weights.push_back(0.0);
  return model;
}

// `model` with the product of the variables a and b added as one more term of weight 0.
Model WithProduct(Model model, int a, int b) {
  model.tree.push_back({Op::kVar, static_cast<uint16_t>(a), 1, 0.0});
  model.tree.push_back({Op::kVar, static_cast<uint16_t>(b), 1, 0.0});
  model.tree.push_back({Op::kMul, 0, 1, 0.0});
  model.tree.push_back({Op::kAdd, 0, 1, 0.0});
  UpdateLengths(model.tree);
  model.term_roots = SplitTerms(model.tree);
  model.weights.push_back(0.0);
  return model;
}

// Whether one of `model`'s terms is the product of the variables a and b.
bool HasProduct(const Model& model, int a, int b, const std::vector<std::string>& names) {
  const std::string& x = names[static_cast<size_t>(a)];
  const std::string& y = names[static_cast<size_t>(b)];
  for (const int root : model.term_roots) {
    const std::string term = ToString(model.tree, root, names);  // "(v * r)"
    if (term == "(" + x + " * " + y + ")" || term == "(" + y + " * " + x + ")") return true;
  }
  return false;
}

// The rigid body's centripetal terms in body axes, u' += c v r and v' += c u r, offered to the
// chosen equations of u and v that lack them (each of weight 0, for the simulation refit to size;
// kinematics_offer). Returns the states offered one.
std::vector<std::string> OfferKinematics(const std::vector<std::string>& states,
                                         const GpProblem& all, std::vector<Model>& offered) {
  std::vector<std::string> names;
  const int u = Index(all, "u"), v = Index(all, "v"), r = Index(all, "r");
  if (u < 0 || v < 0 || r < 0) return names;
  for (size_t i = 0; i < states.size(); ++i) {
    const int other = states[i] == "u" ? v : states[i] == "v" ? u : -1;
    if (other < 0 || HasProduct(offered[i], other, r, all.names)) continue;
    offered[i] = WithProduct(offered[i], other, r);
    names.push_back(states[i]);
  }
  return names;
}

// The weights refitted by simulation error, each chosen equation that does not damp its own
// state (by `rule`, Damps) first offered a linear term in it, of weight 0, for the simulation
// refit to size: the linear damping every hull has (X_u u, Y_v v, N_r r), which a real log's
// noisy derivative rarely shows, although it sets a free run's course over minutes (issue 38:
// on the Esso Osaka runs GP's surge and sway had none and diverged). The offer stays only when that
// refit is accepted (it lowers the simulation error of the fit and the validation parts, and
// free-runs the record); otherwise the equations are refitted as they were chosen. `damped` lists
// the states offered and kept; `kinematic` those offered the centripetal term (OfferKinematics)
// in the same refit.
SimulationRefit RefineWithDamping(const PreparedData& prepared,
                                  const std::vector<std::string>& states, GpProblem* all,
                                  const std::vector<DerivedColumn>& derived, long train_rows,
                                  double horizon_s, const GpIdentifyOptions& options,
                                  std::vector<Model>* bests, std::vector<std::string>* damped,
                                  std::vector<std::string>* kinematic) {
  std::vector<Model> offered = *bests;
  std::vector<std::string> names;
  for (size_t i = 0; i < states.size(); ++i) {
    const int var = Index(*all, states[i]);
    if (options.damping_offer == DampingOffer::kNone ||
        Damps(offered[i], var, *all, derived, prepared.data.t(), options.damping_offer))
      continue;
    offered[i] = WithTerm(offered[i], var);
    names.push_back(states[i]);
  }
  std::vector<std::string> coupled;
  if (options.kinematics_offer) coupled = OfferKinematics(states, *all, offered);
  if (!names.empty() || !coupled.empty()) {
    SimulationRefit refit =
        RefineBySimulation(prepared, states, all, derived, train_rows, horizon_s, &offered);
    if (refit.accepted) {
      *bests = std::move(offered);
      *damped = std::move(names);
      *kinematic = std::move(coupled);
      return refit;
    }
  }
  return RefineBySimulation(prepared, states, all, derived, train_rows, horizon_s, bests);
}

// The equation error's r^2 of the refitted weights, on every row.
double RefittedR2(const PreparedData& prepared, const std::string& state, const Model& best,
                  const std::vector<Eigen::VectorXd>& variables) {
  const Eigen::VectorXd y = prepared.data[state + "_dot"];
  const double sst = (y.array() - y.mean()).square().sum();
  return sst > 0 ? 1.0 - (y - Predict(best, variables)).squaredNorm() / sst : 0.0;
}

nlohmann::json ParetoJson(const GpResult& r) {
  nlohmann::json pareto = nlohmann::json::array();
  for (const ParetoPoint& p : r.pareto)
    pareto.push_back(
        {{"size", p.size}, {"mse", p.mse}, {"r2_heldout", p.r2_heldout}, {"equation", p.equation}});
  return pareto;
}

nlohmann::json LogJson(const GpResult& r) {
  nlohmann::json log = nlohmann::json::array();
  for (const GenerationLog& g : r.log)
    log.push_back({{"generation", g.generation},
                   {"best_fitness", g.best_fitness},
                   {"best_r2", g.best_r2},
                   {"best_size", g.best_size},
                   {"mean_size", g.mean_size}});
  return log;
}

// Why the model selection chose what it did, for a validation part of fraction `f`.
std::string SelectionReason(const Selection& selection, double horizon_s, double f) {
  return std::string(selection.free_run_diverged
                         ? "every combination tried diverged in a free run of the training "
                           "record; the candidate with the smallest"
                         : "the smallest candidate within one standard error of the smallest") +
         " short-horizon simulation error (" + FormatNumber(horizon_s) +
         " s segments, the other states as measured) on the last " + FormatNumber(100.0 * f) +
         " % of the training record" +
         (selection.rejected_for_divergence > 0
              ? ", after " + std::to_string(selection.rejected_for_divergence) +
                    " better ones diverged in a free run of the training record"
              : ", and it free-runs the training record within bounds");
}

// Which of state i's candidates `models` was chosen, each one's score when they were scored
// (`select`), and why.
nlohmann::json ChosenJson(const std::vector<Model>& models, size_t i, const Selection& selection,
                          bool select, double horizon_s, double f,
                          const std::vector<std::string>& names) {
  nlohmann::json chosen = {{"candidate", CandidateJson(models[selection.chosen[i]], names)}};
  if (select) {
    nlohmann::json scored = nlohmann::json::array();
    for (const ScoredCandidate& c : selection.candidate_scores[i]) {
      nlohmann::json j = CandidateJson(models[c.index], names);
      j["short_horizon_error"] = c.score;
      scored.push_back(j);
    }
    chosen["candidates"] = scored;
    chosen["short_horizon_error"] = selection.scores[i];
    chosen["standard_error"] = selection.standard_errors[i];
    chosen["free_run_diverged"] = selection.free_run_diverged;
    chosen["reason"] = SelectionReason(selection, horizon_s, f);
  } else {
    chosen["reason"] = f > 0 ? "a state has no variable of its own to simulate: the search's best"
                             : "no validation part (--validation-fraction 0): the search's best";
  }
  return chosen;
}

// How the weights were fitted: by equation error, or (`refine`) then by simulation error.
nlohmann::json WeightsJson(const SimulationRefit& refit, bool refine, double horizon_s) {
  if (!refine) return {{"fit", "equation"}};
  return {{"fit", "simulation"},
          {"accepted", refit.accepted},
          {"reason", refit.reason},
          {"horizon_s", horizon_s},
          {"segments", refit.segments},
          {"validation_segments", refit.validation_segments},
          {"iterations", refit.iterations},
          {"short_horizon_error_before", refit.initial_error},
          {"short_horizon_error_after", refit.final_error},
          {"validation_error_before", refit.validation_error_before},
          {"validation_error_after", refit.validation_error_after},
          {"free_run_error_before", refit.free_run_error_before},
          {"free_run_error_after", refit.free_run_error_after}};
}

}  // namespace

GpIdentification IdentifyWithGp(
    const PreparedData& given, const std::vector<std::string>& states,
    const std::vector<std::string>& variables, const std::vector<std::string>& inputs,
    const GpIdentifyOptions& options,
    const std::function<void(const std::string&, const GenerationLog&)>& progress) {
  const double f = options.validation_fraction;
  const ValidationSplit split = SplitForValidation(given, f);
  const PreparedData& prepared = split.reordered ? *split.reordered : given;
  GpProblem all = MeasuredVariables(prepared, variables, inputs);
  std::vector<DerivedColumn> derived;
  AddFeatures(options.features, prepared, &all, &derived);
  const long train_rows = TrainRows(prepared.data.rows(), f, split);

  GpIdentification out;
  std::vector<GpResult> results;
  std::vector<StateCandidates> candidates =
      SearchStates(prepared, states, train_rows, options.search, progress, &all, &results,
                   &out.node_evaluations);
  if (options.complete_terms) {
    // after the search, which does not draw them
    AddFeatures(options.completion_features, prepared, &all, &derived);
    CompleteCandidates(prepared, states, all, derived, train_rows, options.search, &candidates);
  }

  Selection selection;
  selection.chosen.assign(states.size(), 0);
  const bool select = f > 0 && AllAmong(states, all.names);
  if (select) {
    const LentVariables lent(prepared, &all, train_rows, options.horizon_s, derived);
    selection = SelectModels(lent.data(), candidates);
  }

  // The chosen terms refitted on every row by equation error, then (when asked) by simulation.
  const int surge = AsternSurge(states, all);
  std::vector<std::string> symmetric;  // the states whose damping was written with |u|
  std::vector<Model> bests = FitChosen(prepared, states, candidates, selection, options.search,
                                       select, surge, &all, &symmetric);
  SimulationRefit refit;
  const bool refine = select && options.weight_fit == WeightFit::kSimulation;
  std::vector<std::string> damped, kinematic;
  if (refine)
    refit = RefineWithDamping(prepared, states, &all, derived, train_rows, options.horizon_s,
                              options, &bests, &damped, &kinematic);

  for (size_t i = 0; i < states.size(); ++i) {
    const std::string& state = states[i];
    const GpResult& r = results[i];
    Model& best = bests[i];
    if (refit.accepted) best.r2 = RefittedR2(prepared, state, best, all.variables);
    out.equations[state] = best.Equation(all.names);
    out.parameters[state + ".bias"] = best.bias;
    for (size_t t = 0; t < best.weights.size(); ++t)
      out.parameters[state + ".w" + std::to_string(t + 1)] = best.weights[t];
    nlohmann::json chosen =
        ChosenJson(candidates[i].models, i, selection, select, options.horizon_s, f, all.names);
    chosen["weights"] = WeightsJson(refit, refine, options.horizon_s);
    // Whether the equation was offered its own state as a damping term, which the refit kept.
    chosen["weights"]["damping_term_added"] = std::ranges::find(damped, state) != damped.end();
    // Whether it was offered the centripetal term (kinematics_offer), which the refit kept.
    if (options.kinematics_offer)
      chosen["weights"]["kinematic_term_added"] =
          std::ranges::find(kinematic, state) != kinematic.end();
    // Whether the chosen equation's damping was written with |u| for astern (astern_symmetry.h).
    chosen["astern_symmetric"] = std::ranges::find(symmetric, state) != symmetric.end();
    out.details[state] = {{"r2_train", best.r2},          {"r2_heldout", best.r2_heldout},
                          {"size", best.Size()},          {"generations", r.log.size()},
                          {"restarts", r.restarts},       {"stop_reason", r.stop_reason},
                          {"evaluations", r.evaluations}, {"selection", chosen},
                          {"pareto", ParetoJson(r)},      {"log", LogJson(r)}};
  }
  return out;
}

}  // namespace usvid::gp
