// `gp`: GP-SR with orthogonal least squares (methods/gp/gp_identify.h), registered in
// methods/method_list.h.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "core/error.h"
#include "core/parse_number.h"
#include "effects/effect.h"
#include "methods/channel_fit.h"
#include "methods/gp/gp_identify.h"
#include "methods/gp/grey_box.h"
#include "methods/gp/term_selection.h"
#include "methods/method.h"
#include "methods/regime_features.h"
#include "preprocessing/rudder_inflow.h"
#include "simulation/vessel_simulator.h"

namespace usvid {
namespace {

std::vector<OptionSpec> GpOptionSpecs() {
  // The defaults are the search's and the identification's own (search.h, gp_identify.h).
  const gp::GpOptions d;
  const gp::GpIdentifyOptions di;
  return {
      ChoiceOption("preset", "default", {"default", "report"},
                   "default (terms chosen by held-out error, constant optimisation, restarts, "
                   "the model chosen by short-horizon simulation) or report (the reference "
                   "report's Table 3.1 exactly); the options given override it"),
      ListOption("operators", {"+", "-", "*"},
                 {"+", "-", "*", "/", "abs", "tanh", "sin", "cos", "exp", "sqrt"},
                 "the functions trees are built of (the report's: +,-,*)"),
      IntegerOption("population", d.population, 4, 1e6, "trees per generation"),
      IntegerOption("generations", d.generations, 1, 1e6, "most generations"),
      IntegerOption("max_depth", d.max_depth, 2, 17, "deepest tree"),
      NumberOption("ols_threshold", std::nullopt, 0, 1,
                   "cut terms whose error reduction ratio is below this (the report's 0.05); "
                   "none: the number of terms chosen by held-out error",
                   /*min_exclusive=*/false, /*max_exclusive=*/true),
      NumberOption("validation_fraction", di.validation_fraction, 0, 0.5,
                   "the last share of the record on which the model is chosen among the Pareto "
                   "candidates by short-horizon simulation (0: none)"),
      NumberOption("horizon_s", std::nullopt, 0, 600,
                   "seconds of each short-horizon simulation that chooses the model and refits "
                   "its weights; none: " +
                       FormatNumber(di.horizon_s) + ", or " + FormatNumber(kRegimeHorizonS) +
                       " on a record with regime features",
                   /*min_exclusive=*/true),
      IntegerOption("constant_iterations", d.constant_iterations, 0, 1000,
                    "Levenberg-Marquardt iterations on the constants inside terms, per elite "
                    "(0: none)"),
      IntegerOption("restarts", d.restarts, 0, 1000,
                    "restarts on stagnation before the search stops"),
      ChoiceOption("fitness", "r2", {"r2", "mse"}, "r2 (held-out, with a size penalty) or mse"),
      ChoiceOption("fit", "simulation", {"simulation", "equation"},
                   "the chosen terms' weights by equation error, then by short-horizon "
                   "simulation error (simulation), or by equation error alone; the report "
                   "preset's: equation"),
      ChoiceOption("damping", "undamped", {"undamped", "every-row", "none"},
                   "which chosen equations the simulation refit offers a linear damping term in "
                   "their own state, kept if the refit is: those that do not damp it on average "
                   "over some record (undamped), or at every row (every-row), or none"),
      ChoiceOption("kinematics", "none", {"none", "offer"},
                   "with the simulation refit, offer surge the centripetal v*r and sway u*r where "
                   "the chosen equation of u or v lacks it, kept if the refit is (offer: the rigid "
                   "body's terms in body axes, which a log's noisy surge derivative hides; on Esso "
                   "Osaka GP's surge had none and kept its speed through the turning circles), or "
                   "not (none)"),
      ChoiceOption("yaw_bias", "equation", {"equation", "zigzag"},
                   "r's constant as the fit left it (equation), or set so that the model, "
                   "replayed closed-loop on each zig-zag among the training records, has their "
                   "first and second overshoots (zigzag; metrics/yaw_bias_calibration.h, needs a "
                   "vessel for the replay's rudder): closer overshoots, a heading that drifts in "
                   "a free run under the recorded rudder"),
      IntegerOption("fit_rows", d.fit_rows, 0, kUnbounded,
                    "rows the search scores on, spread over the record (0: all)"),
      RegimeFeaturesOption(kGpFroudeHinges),
      FlagOption("rudder_inflow",
                 "a rudder's force at its inflow speed among the variables: delta times |u| u, "
                 "u n+ and n+ n+ (docs/baselines.md#the-rudders-inflow), for records that span "
                 "propeller speeds (on one zig-zag at one speed it cost a seed its free run)"),
      TextOption("base", std::nullopt,
                 "grey-box: search additive corrections to this vessel's model (a vessel name or "
                 "file; 'vessel': --vessel with its --params) and keep those that its free runs "
                 "on each record's held-out end support (docs/gp.md#grey-box)"),
      ChoiceOption("choose", "closed-loop", {"closed-loop", "free-run"},
                   "with base: the model among the corrections weighed, by the held-out free "
                   "runs among those whose training zig-zags and turning circles, replayed "
                   "closed-loop, are no worse than the vessel's (closed-loop), or by the free "
                   "runs alone (free-run)"),
  };
}

// GP's options: the preset's, with the options given in their place; throws InputError for an
// option out of the search's own range (GpOptions::IsValid).
gp::GpIdentifyOptions GpOptionsFor(const IdentifyRequest& request, const MethodOptions& o) {
  gp::GpIdentifyOptions g;
  const bool report = o.Text("preset") == "report";
  if (report) {
    g.search = gp::ReportOptions();
    g.validation_fraction = 0.0;
  }
  gp::GpOptions& s = g.search;
  std::string operators;
  for (const std::string& op : o.List("operators"))
    operators += (operators.empty() ? "" : ",") + op;
  // Under a preset, its values stay where no option was given.
  auto use = [&](const char* key) { return o.Given(key) || !report; };
  if (use("operators")) s.functions = gp::ParseOperators(operators);
  if (use("population")) s.population = static_cast<int>(o.Integer("population"));
  if (use("generations")) s.generations = static_cast<int>(o.Integer("generations"));
  if (use("max_depth")) s.max_depth = static_cast<int>(o.Integer("max_depth"));
  if (use("restarts")) s.restarts = static_cast<int>(o.Integer("restarts"));
  if (use("constant_iterations"))
    s.constant_iterations = static_cast<int>(o.Integer("constant_iterations"));
  if (use("fit_rows")) s.fit_rows = o.Integer("fit_rows");
  if (o.Given("ols_threshold")) s.ols_threshold = o.Number("ols_threshold");
  s.fitness_mse = o.Text("fitness") == "mse";
  s.seed = request.seed;
  s.threads = request.threads;
  if (use("validation_fraction")) g.validation_fraction = o.Number("validation_fraction");
  g.horizon_s = o.OptionalNumber("horizon_s").value_or(g.horizon_s);
  const bool simulation = o.Given("fit") ? o.Text("fit") == "simulation" : !report;
  g.weight_fit = simulation ? gp::WeightFit::kSimulation : gp::WeightFit::kEquation;
  g.damping_offer = o.Text("damping") == "every-row" ? gp::DampingOffer::kEveryRow
                    : o.Text("damping") == "none"    ? gp::DampingOffer::kNone
                                                     : gp::DampingOffer::kUndamped;
  g.kinematics_offer = o.Text("kinematics") == "offer";
  if (std::string error; !s.IsValid(&error))
    throw InputError("method gp: option " + error);  // IsValid names the field, the option's key
  return g;
}

nlohmann::json GpDetails(const MethodOptions& o, const gp::GpIdentifyOptions& gpo,
                         const gp::GpIdentification& gp, const nlohmann::json& features) {
  const gp::GpOptions& so = gpo.search;
  const char* weight_fit = gpo.weight_fit == gp::WeightFit::kSimulation ? "simulation" : "equation";
  return {{"preset", o.Text("preset")},
          {"operators", gp::OperatorList(so.functions)},
          {"features", features},
          {"term_completion", gpo.complete_terms},
          {"population", so.population},
          {"generations", so.generations},
          {"max_depth", so.max_depth},
          {"crossover", so.crossover},
          {"mutation", so.mutation},
          {"term_selection", so.ols_threshold ? "ols threshold" : "held-out blocks"},
          {"ols_threshold",
           so.ols_threshold ? nlohmann::json(*so.ols_threshold) : nlohmann::json(nullptr)},
          {"held_out_blocks", so.ols_threshold ? 0 : gp::kHeldOutBlocks},
          {"term_mutation", so.term_mutation},
          {"restarts", so.restarts},
          {"constant_iterations", so.constant_iterations},
          {"constant_elites", so.constant_elites},
          {"validation_fraction", gpo.validation_fraction},
          {"horizon_s", gpo.horizon_s},
          {"weight_fit", weight_fit},
          {"damping", o.Text("damping")},
          {"kinematics", o.Text("kinematics")},
          {"fitness", o.Text("fitness")},
          {"fit_rows", so.fit_rows},
          {"node_evaluations", gp.node_evaluations},
          {"equations", gp.details}};
}

// The options as the search ran them: a preset's values where none was given.
nlohmann::json UsedOptions(const MethodOptions& o, const gp::GpIdentifyOptions& gpo) {
  nlohmann::json used = o.Json();
  const gp::GpOptions& s = gpo.search;
  std::vector<std::string> operators;
  for (gp::Op op : s.functions) operators.push_back(gp::Symbol(op));
  used["operators"] = operators;
  used["population"] = s.population;
  used["generations"] = s.generations;
  used["max_depth"] = s.max_depth;
  used["restarts"] = s.restarts;
  used["constant_iterations"] = s.constant_iterations;
  used["fit_rows"] = s.fit_rows;
  used["ols_threshold"] = s.ols_threshold ? nlohmann::json(*s.ols_threshold) : nlohmann::json();
  used["validation_fraction"] = gpo.validation_fraction;
  used["horizon_s"] = gpo.horizon_s;
  used["fit"] = gpo.weight_fit == gp::WeightFit::kSimulation ? "simulation" : "equation";
  return used;
}

// A free-run error, or "diverged".
nlohmann::json FiniteOrDiverged(double error) {
  return std::isfinite(error) ? nlohmann::json(error) : nlohmann::json("diverged");
}

// What a grey-box fit weighed: every correction tried in each round, and the alternatives
// (methods/gp/grey_box.h) the closed-loop choice weighs.
void WriteGreyBoxSearch(const gp::GreyBoxResult& r, nlohmann::json& model) {
  nlohmann::json tried = nlohmann::json::array(), alternatives = nlohmann::json::array();
  for (const gp::GreyBoxCandidate& c : r.tried) {
    tried.push_back({{"state", c.state},
                     {"correction", c.equation},
                     {"round", c.round},
                     {"free_run_error", FiniteOrDiverged(c.free_run_error)}});
    if (c.free_run_error_at_least) tried.back()["free_run_error_at_least"] = true;
  }
  for (const gp::GreyBoxAlternative& a : r.alternatives) {
    nlohmann::json terms = nlohmann::json::array();
    for (const Effect& e : a.terms) terms.push_back(EffectToJson(e));
    alternatives.push_back({{"label", a.label},
                            {"corrections", a.corrections},
                            {"effects", terms},
                            {"free_run_error", FiniteOrDiverged(a.free_run_error)}});
    if (a.free_run_error_at_least) alternatives.back()["free_run_error_at_least"] = true;
  }
  model["gp"]["tried"] = tried;
  model["alternatives"] = alternatives;
}

// The base a grey-box fit corrects ('vessel': --vessel), refusing the options of whole
// equations that have no part in it.
VesselRef GreyBoxBase(const IdentifyRequest& request, const MethodOptions& o) {
  for (const char* key : {"validation_fraction", "horizon_s", "fit", "damping", "kinematics"})
    if (o.Given(key))
      throw InputError(std::string("method gp: option ") + key +
                       " has no part in a grey-box fit (--base), whose corrections are chosen by "
                       "the vessel's free runs (docs/gp.md#grey-box)");
  if (o.Text("yaw_bias") != "equation")
    throw InputError("method gp: yaw_bias=" + o.Text("yaw_bias") +
                     " calibrates an equation model; a grey-box fit (--base) has the vessel's");
  if (const std::string f = o.Text("features"); f != "auto" && f != "none")
    throw InputError("method gp: features=" + f +
                     " is for whole equations; a grey-box fit (--base) searches on the vessel's "
                     "states and inputs (and rudder_inflow)");
  const VesselRef base = o.Text("base") == "vessel" ? request.vessel : VesselRef(o.Text("base"));
  if (base.empty())
    throw InputError("method gp: base=vessel needs --vessel (or give the vessel: --base NAME)");
  return base;
}

// --base: the corrections to a vessel's model (methods/gp/grey_box.h); a vessel model whose
// effects are the kept terms.
nlohmann::json IdentifyGreyBoxModel(const Dataset& data, const IdentifyRequest& request,
                                    const MethodOptions& o, const gp::GpIdentifyOptions& gpo) {
  const auto start = std::chrono::steady_clock::now();
  const VesselRef base = GreyBoxBase(request, o);
  const VesselInfo& info = base.Info();
  const std::vector<double> params = base == request.vessel && !request.start_params.empty()
                                         ? request.start_params
                                         : info.default_params;
  gp::GreyBoxOptions g;
  g.search = gpo.search;
  if (o.Flag("rudder_inflow")) {
    std::vector<std::string> channels = info.states;
    channels.insert(channels.end(), info.inputs.begin(), info.inputs.end());
    for (const RudderInflowTerm& term : RudderInflowTerms(channels))
      g.features.push_back({term.name, term.expression});
  }
  const gp::GreyBoxResult r = gp::IdentifyGreyBox(base, params, data, g);
  nlohmann::json parameters = nlohmann::json::object(), effects = nlohmann::json::array(),
                 features = nlohmann::json::object();
  for (size_t i = 0; i < info.params.size(); ++i) parameters[info.params[i]] = params[i];
  for (const Effect& e : r.terms) effects.push_back(EffectToJson(e));
  for (const DerivedVariable& f : g.features) features[f.name] = f.expression;
  std::vector<std::string> states;
  for (const std::string& s : info.states)
    if (!IsPositionOrHeading(s)) states.push_back(s);
  nlohmann::json model = {
      {"method", request.method},
      {"vessel", base.Name()},
      {"states", states},
      {"inputs", info.inputs},
      {"parameters", parameters},
      {"effects", effects},
      {"corrections", r.corrections},  // the vessel plus these, per state: the effects' sums
      {"gp",
       {{"base", base.Name()},
        {"operators", gp::OperatorList(gpo.search.functions)},
        {"features", features},
        {"population", gpo.search.population},
        {"generations", gpo.search.generations},
        {"heldout_fraction", g.heldout},
        {"vessel_free_run_error", FiniteOrDiverged(r.vessel_free_run_error)},
        {"free_run_error", FiniteOrDiverged(r.free_run_error)},
        {"node_evaluations", r.node_evaluations}}},
      {"options", UsedOptions(o, gpo)}};
  WriteGreyBoxSearch(r, model);
  model["train"] = {
      {"data", request.data_name},
      {"samples", data.rows()},
      {"seconds", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()}};
  // The choice among the alternatives by the training records' closed-loop tests: a replay,
  // which the caller runs (metrics/closed_loop_choice.h, CalibrateRequested).
  if (o.Text("choose") == "closed-loop") model["calibration"] = {{"choose", "closed-loop"}};
  return model;
}

nlohmann::json IdentifyGpModel(const Dataset& data, const IdentifyRequest& request,
                               const MethodOptions& o, const Logger& log) {
  gp::GpIdentifyOptions gpo = GpOptionsFor(request, o);
  if (o.Has("base")) return IdentifyGreyBoxModel(data, request, o, gpo);
  if (o.Given("choose"))
    throw InputError(
        "method gp: option choose picks among a grey-box fit's corrections; give "
        "it with base (docs/gp.md#grey-box)");
  ChannelFit fit = PrepareChannelFit(data, request, DefaultChannels(request, data), log);
  const double froude_per_speed =
      request.vessel.empty() ? 0.0 : request.vessel.Simulator().FroudeNumber(1.0).value_or(0.0);
  const std::string features_choice = o.Text("features");
  gpo.features =
      RegimeFeatures(features_choice, froude_per_speed, fit.prepared.data, kGpFroudeHinges);
  // Term completion where it was measured to help: on records with regime features (odin-hs's
  // zig-zag, docs/gp.md); on KVLCC2's single zig-zag it cost GP the heading.
  gpo.complete_terms = !gpo.features.empty();
  // A hull that crosses regimes holds its speed where the resistance is steep (the knee of
  // odin-hs's hump): a surge equation a few percent off there shows over 30 s, not over 10 s
  // (docs/gp.md).
  if (gpo.complete_terms && !o.Has("horizon_s")) gpo.horizon_s = kRegimeHorizonS;
  if (gpo.complete_terms && features_choice != "froude")
    gpo.completion_features =
        RegimeFeatures(features_choice, froude_per_speed, fit.prepared.data, kSindyFroudeHinges);
  // The rudder's force at its inflow speed among the variables, after the rules above, which are
  // the regime features' alone.
  if (o.Flag("rudder_inflow")) {
    std::vector<std::string> channels = fit.channels.variables;
    channels.insert(channels.end(), fit.channels.inputs.begin(), fit.channels.inputs.end());
    for (const RudderInflowTerm& term : RudderInflowTerms(channels))
      gpo.features.push_back({term.name, term.expression});
  }
  nlohmann::json features = nlohmann::json::object();  // name -> expression
  for (const DerivedVariable& f : gpo.features) features[f.name] = f.expression;
  const gp::GpIdentification gp = gp::IdentifyWithGp(
      fit.prepared, fit.channels.states, fit.channels.variables, fit.channels.inputs, gpo,
      [&](const std::string& state, const gp::GenerationLog& g) {
        char line[200];
        std::snprintf(line, sizeof line,
                      "%s' generation %d: best r2 %.6f, size %zu, fitness %.6f, "
                      "%.3g node evaluations/s",
                      state.c_str(), g.generation, g.best_r2, g.best_size, g.best_fitness,
                      g.node_evals_per_second);
        Log(log, line);
      });
  fit.model["parameters"] = gp.parameters;
  fit.model["equations"] = gp.equations;
  fit.model["gp"] = GpDetails(o, gpo, gp, features);
  fit.model["options"] = UsedOptions(o, gpo);
  // r's constant from the training zig-zags' overshoots: a closed-loop replay, which the caller
  // runs (metrics/yaw_bias_calibration.h, CalibrateRequested), since it is the metrics' own.
  if (o.Text("yaw_bias") == "zigzag" && gp.equations.contains("r"))
    fit.model["calibration"] = {{"yaw_bias", "zigzag"}};
  SetTrain(fit, request);
  return fit.model;
}

}  // namespace

Method GpMethod() {
  Method m;
  m.name = std::string(gp::kMethodName);
  m.summary = "GP-SR with orthogonal least squares";
  m.options = GpOptionSpecs();
  m.identify = IdentifyGpModel;
  m.channel_inputs = true;
  m.any_inputs = true;
  m.seeded = true;
  m.label_option = "operators";
  m.relative_cost = 30.0;  // the search, the selection's simulations and the weights' refit
  m.cost_scale = [](const MethodOptions& o) {  // the search's share of it
    const gp::GpOptions d;
    return static_cast<double>(o.Integer("population") * o.Integer("generations")) /
           (static_cast<double>(d.population) * d.generations);
  };
  return m;
}

}  // namespace usvid
