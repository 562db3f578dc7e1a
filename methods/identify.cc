#include "methods/identify.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <set>
#include <type_traits>

#include "core/derived_channels.h"
#include "core/error.h"
#include "core/parse_number.h"
#include "methods/eb_lr/eb_lr.h"
#include "core/expression.h"
#include "methods/fossen_ceres/fossen_fit.h"
#include "methods/fossen_ceres/fossen_models.h"
#include "methods/fossen_ceres/jet_force_model.h"
#include "methods/gp/gp_identify.h"
#include "methods/gp/term_selection.h"
#include "methods/nomoto/nomoto.h"
#include "methods/hybrid/hybrid.h"
#include "methods/refit/refit.h"
#include "methods/regime_features.h"
#include "methods/sindy/sindy.h"
#include "preprocessing/delay_estimation.h"
#include "preprocessing/waterjet_forces.h"
#include "simulation/segment_error.h"
#include "simulation/vessel_simulator.h"
#include "simulators/odin3dof.h"

namespace usvid {
namespace {

using Logger = std::function<void(const std::string&)>;

void Log(const Logger& log, const std::string& line) {
  if (log) log(line);
}

// fossen-ceres: a parametric Fossen 3-DOF model (odin3dof's, the same driven through the
// waterjet or the rudder-propeller input map, or the high-speed form on the jets' forces),
// equation error then multiple shooting.
template <typename Model>
nlohmann::json IdentifyFossen(const IdentifyRequest& o, const Dataset& data,
                              const PreparedData& prepared, const Logger& log) {
  constexpr bool kOdin3Dof = std::is_same_v<Model, fossen::Odin3DofModel>;
  fossen::FossenOptions fo;
  fo.segment_s = o.segment_s > 0 ? o.segment_s : 10.0;
  fo.robust = o.robust;
  // One thread for Ceres: its parallel evaluation sums the cost in a thread-dependent order, and
  // the last digits of the fit would differ between 1 and 2 threads.
  fo.threads = 1;
  const auto eq = fossen::FitEquationErrorFor<Model>(prepared, fo);
  Log(log, "equation-error fit: " + eq.termination);
  auto fit = eq;
  if (o.fit_mode == "simulation") {
    fit = fossen::FitSimulationErrorFor<Model>(prepared, eq.params, fo);
    Log(log, "simulation-error fit (multiple shooting): " + fit.termination);
  }
  nlohmann::json params = nlohmann::json::object(), sd = nlohmann::json::object(),
                 eq_params = nlohmann::json::object();
  for (int i = 0; i < Model::kParams; ++i) {
    const std::string name(Model::kParamNames[i]);
    params[name] = fit.params[i];
    sd[name] = fit.sd[i];
    eq_params[name] = eq.params[i];
  }
  const nlohmann::json equations = fossen::EquationsFor<Model>(fit.params);
  nlohmann::json refined = nullptr;
  if (!kOdin3Dof && prepared.delay_estimate) {
    Log(log,
        "delay not refined: the " + std::string(Model::kName) + " model is no registered vessel");
  } else if (prepared.delay_estimate) {
    // The delay to a fraction of a sample: NLopt (DIRECT-L, then Sbplx) on the segmented
    // simulation error of the fitted model on the data as recorded.
    const VesselSimulator& sim = FindVessel("odin3dof");
    const std::vector<double> p(fit.params.begin(), fit.params.end());
    auto cost = [&](const std::vector<double>& d) {
      EffectValues<double> e;
      e.delay_s = d[0];
      return SegmentedSimulationError(sim, p, e, data, {"u", "v", "r"}, fo.segment_s);
    };
    const DelayEstimate d =
        ContinuousDelay(cost, 1, o.preprocess.max_delay_s, {prepared.delay_s}, 60);
    refined = d.delay_s;
    Log(log, "delay refined on the simulation error: " + std::to_string(d.delay_s) + " s");
  }
  return {{"parameters", params},
          {"equations", equations},
          {"fossen",
           {{"model", std::string(Model::kName)},
            {"mode", o.fit_mode},
            {"segment_s", fo.segment_s},
            {"robust", o.robust},
            {"parameter_sd", sd},
            {"covariance_ok", fit.covariance_ok},
            {"termination", fit.termination},
            {"converged", fit.converged},
            {"initial_cost", fit.initial_cost},
            {"final_cost", fit.final_cost},
            {"iterations", fit.iterations},
            {"equation_error_parameters", eq_params},
            {"delay_refined_s", refined}}}};
}

// The vessel's states less `excluded`, in order.
std::vector<std::string> StatesExcept(const VesselInfo& info,
                                      const std::set<std::string>& excluded) {
  std::vector<std::string> out;
  for (const std::string& s : info.states)
    if (!excluded.contains(s)) out.push_back(s);
  return out;
}

// Positions and heading follow from the kinematics and need no equation; the dynamics do not
// depend on them either, except the msd's spring on x. Actuator feedback is left out.
const std::set<std::string> kNotVariables = {"north",        "east",           "psi", "chi", "rpm",
                                             "nozzle_angle", "bucket_position"};

// nominal: the vessel as it is (its defaults, or --params), nothing fitted: the physics-based
// prediction every identified model has to beat.
nlohmann::json NominalModel(const Dataset& data, const IdentifyRequest& o) {
  if (o.vessel.empty()) throw InputError("--method nominal: needs --vessel");
  const VesselInfo& info = FindVessel(o.vessel).Info();
  const std::vector<double>& p = o.start_params.empty() ? info.default_params : o.start_params;
  nlohmann::json params = nlohmann::json::object();
  for (size_t i = 0; i < p.size(); ++i) params[info.params[i]] = p[i];
  return {{"method", "nominal"},
          {"vessel", o.vessel},
          {"states", StatesExcept(info, kNotVariables)},
          {"inputs", info.inputs},
          {"parameters", params},
          {"train", {{"data", o.data_name}, {"samples", data.rows()}, {"seconds", 0.0}}}};
}

// The parameters of a vessel fit, and how it went (refit's and hybrid's model.json).
nlohmann::json RefitParameters(const RefitResult& fit) {
  nlohmann::json params = nlohmann::json::object();
  for (size_t i = 0; i < fit.names.size(); ++i) params[fit.names[i]] = fit.params[i];
  return params;
}

nlohmann::json RefitDetails(const RefitResult& fit, double prior_sd) {
  nlohmann::json start = nlohmann::json::object(), ratio = nlohmann::json::object();
  for (size_t i = 0; i < fit.names.size(); ++i) start[fit.names[i]] = fit.start[i];
  for (const std::string& n : fit.free) {
    const size_t i = std::find(fit.names.begin(), fit.names.end(), n) - fit.names.begin();
    ratio[n] = fit.start[i] != 0.0 ? fit.params[i] / fit.start[i] : fit.params[i];
  }
  return {{"free", fit.free},
          {"ratio_to_start", ratio},
          {"start", start},
          {"segment_s", fit.segment_s},
          {"prior_sd", prior_sd},
          {"segments", fit.segments},
          {"termination", fit.termination},
          {"converged", fit.converged},
          {"initial_cost", fit.initial_cost},
          {"final_cost", fit.final_cost},
          {"iterations", fit.iterations}};
}

RefitOptions RefitOptionsFor(const IdentifyRequest& o) {
  RefitOptions ro;
  ro.free = o.refit_params;
  ro.segment_s = o.segment_s;
  ro.prior_sd = o.prior_sd;
  ro.threads = 1;  // deterministic, as for fossen-ceres
  return ro;
}

// refit: the vessel's own coefficients (methods/refit/refit.h); a vessel model, no equations.
nlohmann::json IdentifyRefit(const Dataset& data, const IdentifyRequest& o, const Logger& log) {
  if (o.vessel.empty()) throw InputError("--method refit: needs --vessel");
  const VesselInfo& info = FindVessel(o.vessel).Info();
  const RefitResult fit = RefitVessel(
      o.vessel, data, o.start_params.empty() ? info.default_params : o.start_params,
      RefitOptionsFor(o));
  Log(log, "refit of " + std::to_string(fit.free.size()) + " parameters on " +
               std::to_string(fit.segments) + " segments: " + fit.termination);
  return {{"method", "refit"},
          {"vessel", o.vessel},
          {"states", fit.channels},
          {"inputs", info.inputs},
          {"parameters", RefitParameters(fit)},
          {"refit", RefitDetails(fit, o.prior_sd)},
          {"train", {{"data", o.data_name}, {"samples", data.rows()}, {"seconds", fit.seconds}}}};
}

// hybrid: the vessel refitted with the missing terms its residual proposes and held-out
// simulation keeps (methods/hybrid/hybrid.h); a vessel model whose effects are those terms.
nlohmann::json IdentifyHybridModel(const Dataset& data, const IdentifyRequest& o,
                                   const Logger& log) {
  if (o.vessel.empty()) throw InputError("--method hybrid: needs --vessel");
  const VesselInfo& info = FindVessel(o.vessel).Info();
  hybrid::HybridOptions ho;
  ho.refit = RefitOptionsFor(o);
  ho.refit.threads = o.threads > 0 ? o.threads : 1;  // proposals in parallel, each one thread
  ho.max_terms = o.hybrid_terms.value_or(ho.max_terms);
  const hybrid::HybridResult h = hybrid::IdentifyHybrid(
      o.vessel, data, o.start_params.empty() ? info.default_params : o.start_params, ho);
  nlohmann::json proposals = nlohmann::json::array(), rounds = nlohmann::json::array();
  for (const hybrid::TermProposal& p : h.proposals) {
    nlohmann::json j = EffectToJson(p.term);
    j["err"] = p.err;
    proposals.push_back(j);
  }
  for (const hybrid::SelectionRound& r : h.rounds) {
    nlohmann::json errors = nlohmann::json::object();
    for (size_t j = 0; j < r.heldout_error.size(); ++j)
      if (std::isfinite(r.heldout_error[j]))
        errors[EffectLabel(h.proposals[j].term)] = r.heldout_error[j];
    rounds.push_back({{"heldout_error", errors},
                      {"likelihood_ratio", r.likelihood_ratio},
                      {"chosen", r.chosen >= 0 ? EffectLabel(h.proposals[r.chosen].term)
                                               : std::string("none")}});
  }
  nlohmann::json effects = nlohmann::json::array();
  for (const Effect& e : h.fit.terms) effects.push_back(EffectToJson(e));
  Log(log, "hybrid: " + std::to_string(h.fit.terms.size()) + " of " +
               std::to_string(h.proposals.size()) + " proposed terms kept; held-out error " +
               std::to_string(h.vessel_heldout_error) + " -> " + std::to_string(h.heldout_error));
  return {{"method", "hybrid"},
          {"vessel", o.vessel},
          {"states", h.fit.channels},
          {"inputs", info.inputs},
          {"parameters", RefitParameters(h.fit)},
          {"effects", effects},
          {"refit", RefitDetails(h.fit, o.prior_sd)},
          {"hybrid",
           {{"heldout_fraction", ho.heldout},
            {"proposals", proposals},
            {"rounds", rounds},
            {"vessel_heldout_error", h.vessel_heldout_error},
            {"effective_samples", h.effective_samples},
            {"critical_ratio", ho.critical_ratio},
            {"heldout_error", h.heldout_error}}},
          {"train", {{"data", o.data_name}, {"samples", data.rows()}, {"seconds", h.seconds}}}};
}

// GP's options: the preset's, with what the request sets in their place; throws InputError
// for an unknown preset or an option out of its range.
gp::GpIdentifyOptions GpOptionsFor(const IdentifyRequest& o) {
  gp::GpIdentifyOptions g;
  if (o.preset == "report") {
    g.search = gp::ReportOptions();
    g.validation_fraction = 0.0;
  } else if (o.preset != "default") {
    throw InputError("--preset '" + o.preset + "': unknown preset (known: default, report)");
  }
  gp::GpOptions& s = g.search;
  s.functions = gp::ParseOperators(o.operators);
  s.population = o.population.value_or(s.population);
  s.generations = o.generations.value_or(s.generations);
  s.max_depth = o.max_depth.value_or(s.max_depth);
  s.restarts = o.restarts.value_or(s.restarts);
  s.constant_iterations = o.constant_iterations.value_or(s.constant_iterations);
  if (o.ols_threshold) s.ols_threshold = o.ols_threshold;
  s.fit_rows = o.fit_rows.value_or(s.fit_rows);
  s.fitness_mse = o.fitness == "mse";
  s.seed = o.seed;
  s.threads = o.threads;
  g.validation_fraction = o.validation_fraction.value_or(g.validation_fraction);
  g.horizon_s = o.horizon_s.value_or(g.horizon_s);
  g.weight_fit = o.fit_mode == "equation" || o.preset == "report" ? gp::WeightFit::kEquation
                                                                  : gp::WeightFit::kSimulation;
  if (s.population < 4 || s.generations < 1 || s.max_depth < 2 || s.max_depth > 17)
    throw InputError("identify: --population >= 4, --generations >= 1, --max-depth in [2, 17]");
  if (s.ols_threshold && !(*s.ols_threshold >= 0 && *s.ols_threshold < 1))
    throw InputError("--ols-threshold: must be in [0, 1)");
  if (!(g.validation_fraction >= 0 && g.validation_fraction <= 0.5))
    throw InputError(
        "--validation-fraction: must be in [0, 0.5] (the share of the record kept "
        "to choose the model by simulation; 0: none)");
  if (!(g.horizon_s > 0 && g.horizon_s <= 600))
    throw InputError("--horizon: must be in (0, 600] seconds, got " + FormatNumber(g.horizon_s));
  if (s.constant_iterations < 0)
    throw InputError("--constant-iterations: must be >= 0 (0: no constant optimisation)");
  if (s.restarts < 0) throw InputError("--restarts: must be >= 0");
  if (s.fit_rows < 0) throw InputError("--fit-rows: must be >= 0 (0: every row)");
  return g;
}

// eb-lr's options for the request. On the jets' surge force and yaw moment (tau_x, tau_n of
// the waterjet map, docs/baselines.md): the thrust falls with speed by the inlet's momentum drag,
// k jet_flow U; the steady windows follow the commands, which are held, not the forces, which
// slew and carry the sensors' noise; sigma_U is a quartic with a constant, which follows a
// planing hull's resistance hump over the record's speeds (the cubic without a constant does
// not); and m_r is the yaw inertia alone, a constant, since tau_n is a moment (a slope in U took
// m_r through zero within the data).
eb_lr::EbLrOptions EbLrOptionsFor(const IdentifyRequest& o, const std::vector<std::string>& inputs,
                                  const Dataset& data) {
  eb_lr::EbLrOptions eo;
  if (o.preprocess.forces != "waterjet" || inputs != std::vector<std::string>{"tau_x", "tau_n"})
    return eo;
  eo.thrust_loss_channel = "jet_flow";
  eo.sigma_speed_basis = {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}, {0, 2}};
  eo.mass_rate_basis = {{0, 0}};
  if (o.vessel.empty()) return eo;
  const Actuation& a = FindVessel(o.vessel).Info().actuation;
  if (a.thrust_input < 0 || a.yaw_input < 0) return eo;
  std::vector<std::string> commands = {a.input_names[a.thrust_input], a.input_names[a.yaw_input]};
  if (data.Has(commands[0]) && data.Has(commands[1])) eo.held_inputs = std::move(commands);
  return eo;
}

}  // namespace

nlohmann::json Identify(const Dataset& recorded, const IdentifyRequest& o, const Logger& log) {
  // Speed and course where only body velocities were logged (the 2-DOF models need them).
  Dataset data = recorded;
  AddSpeedAndCourse(data);
  AddForces(data, o.preprocess.forces);
  if (o.method != "gp" && o.method != "sindy" && o.method != "eb-lr" &&
      o.method != "fossen-ceres" && o.method != "refit" && o.method != "hybrid" &&
      o.method != "nominal" && o.method != "nomoto")
    throw InputError("--method '" + o.method +
                     "': unknown method (known: gp, sindy, eb-lr, fossen-ceres, refit, hybrid, "
                     "nominal, nomoto)");
  if (o.method != "gp" && o.method != "sindy" && o.features != "auto")
    throw InputError("--features: only gp and sindy take regime features");
  if (o.fit_mode != "simulation" && o.fit_mode != "equation")
    throw InputError("--fit '" + o.fit_mode + "': unknown (known: simulation, equation)");
  if (o.method == "refit") return IdentifyRefit(data, o, log);
  if (o.method == "hybrid") return IdentifyHybridModel(data, o, log);
  if (o.method == "nominal") return NominalModel(data, o);
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::string> states = o.states, variables = o.states, inputs = o.inputs;
  if (!o.vessel.empty()) {
    const VesselInfo& info = FindVessel(o.vessel).Info();
    if (states.empty()) {
      variables = StatesExcept(info, kNotVariables);
      std::set<std::string> no_equation = kNotVariables;
      no_equation.insert("x");
      states = StatesExcept(info, no_equation);
    }
    // With a force map, the forces it derives stand in for the commands.
    if (inputs.empty())
      inputs = o.preprocess.forces.empty() ? info.inputs : ForceChannels(o.preprocess.forces);
  }
  if (states.empty() || inputs.empty())
    throw InputError("identify: give --vessel, or --states and --inputs");
  if (o.method == "nomoto") {
    // The first-order Nomoto model: the rate of turn from the yaw input.
    if (!o.vessel.empty() && o.states.empty()) {
      const Actuation& a = FindVessel(o.vessel).Info().actuation;
      states = variables = {FindVessel(o.vessel).Info().states[a.rate_state]};
      inputs = {a.input_names[a.yaw_input]};
    }
    if (states.size() != 1 || inputs.size() != 1)
      throw InputError("--method nomoto: needs --states RATE and --inputs YAW (one each)");
  }
  if (o.method == "eb-lr") {
    // The Eriksen-Breivik 2-DOF form: speed U and rate r, driven by thrust and yaw inputs: the
    // commands, or with the waterjet map the jets' surge force and yaw moment.
    if (!o.vessel.empty() && o.states.empty()) {
      const Actuation& a = FindVessel(o.vessel).Info().actuation;
      if (a.thrust_input < 0)
        throw InputError("--method eb-lr: vessel " + o.vessel + " has no thrust input");
      states = variables = {"U", "r"};
      if (o.inputs.empty())
        inputs = o.preprocess.forces == "waterjet"
                     ? std::vector<std::string>{"tau_x", "tau_n"}
                     : std::vector<std::string>{a.input_names[a.thrust_input],
                                                a.input_names[a.yaw_input]};
    }
    if (states.size() != 2 || inputs.size() != 2)
      throw InputError("--method eb-lr: needs --states SPEED,RATE and --inputs THRUST,YAW");
  }
  const std::vector<std::string> kForces = {"tau_x", "tau_y", "tau_n"},
                                 kJetForces = {"tau_x", "tau_y", "tau_n", "jet_flow"},
                                 kWaterjets = {"throttle", "nozzle", "bucket"},
                                 kRudder = {"delta", "rev"};
  if (o.method == "fossen-ceres" &&
      (states != std::vector<std::string>{"u", "v", "r"} ||
       (inputs != kForces && inputs != kJetForces && inputs != kWaterjets && inputs != kRudder)))
    throw InputError(
        "--method fossen-ceres: fits the Fossen 3-DOF model, states u,v,r with inputs "
        "tau_x,tau_y,tau_n (--vessel odin3dof), tau_x,tau_y,tau_n,jet_flow with speed-dependent "
        "damping (--vessel odin-hs --forces waterjet), throttle,nozzle,bucket through a "
        "waterjet map (--vessel odin-hs) or delta,rev through a rudder-propeller map (--vessel "
        "kvlcc2)");
  gp::GpIdentifyOptions gpo = GpOptionsFor(o);
  PreprocessOptions pre = o.preprocess;
  // Forces from the actuators' states are continuous (slew-limited actuators): no input steps to
  // break the derivative spline at; every slewing sample would count as one.
  if (!pre.forces.empty()) pre.step_breaks = false;
  PreparedData prepared = Preprocess(data, variables, inputs, pre);
  for (const std::string& note : prepared.notes) Log(log, note);
  nlohmann::json features_json = nlohmann::json::object();  // name -> expression
  if (o.method == "gp" || o.method == "sindy") {
    const double froude_per_speed =
        o.vessel.empty() ? 0.0 : FindVessel(o.vessel).FroudeNumber(1.0).value_or(0.0);
    gpo.features = RegimeFeatures(o.features, froude_per_speed, prepared.data,
                                  o.method == "gp" ? kGpFroudeHinges : kSindyFroudeHinges);
    // Term completion where it was measured to help: on records with regime features
    // (odin-hs's zig-zag, docs/gp.md); on KVLCC2's single zig-zag it cost GP the heading.
    gpo.complete_terms = o.method == "gp" && !gpo.features.empty();
    // A hull that crosses regimes holds its speed where the resistance is steep (the knee of
    // odin-hs's hump): a surge equation a few percent off there shows over 30 s, not over 10 s
    // (docs/gp.md).
    if (gpo.complete_terms && !o.horizon_s) gpo.horizon_s = kRegimeHorizonS;
    if (gpo.complete_terms && o.features != "froude")
      gpo.completion_features =
          RegimeFeatures(o.features, froude_per_speed, prepared.data, kSindyFroudeHinges);
    for (const DerivedVariable& f : gpo.features) features_json[f.name] = f.expression;
  }
  nlohmann::json model = {
      {"method", o.method},
      {"vessel", o.vessel},
      {"states", states},
      {"variables", variables},
      {"inputs", inputs},
      {"seed", o.seed},
      {"preprocessing",
       {{"delay_s", prepared.delay_s},
        {"derivative", pre.derivative.Spec()},
        {"forces", pre.forces.empty() ? nlohmann::json(nullptr) : nlohmann::json(pre.forces)},
        {"step_breaks", pre.step_breaks},
        {"notes", prepared.notes}}}};
  if (o.method == "eb-lr") {
    const eb_lr::EbLrOptions eo = EbLrOptionsFor(o, inputs, data);
    const eb_lr::EbLrIdentification id =
        eb_lr::IdentifyWithEbLr(data, states[0], states[1], inputs[0], inputs[1], eo);
    model["parameters"] = id.parameters;
    model["equations"] = id.equations;
    model["eb_lr"] = id.details;
    if (!eo.thrust_loss_channel.empty() &&
        std::ranges::find(inputs, eo.thrust_loss_channel) == inputs.end())
      model["inputs"].push_back(eo.thrust_loss_channel);
  } else if (o.method == "fossen-ceres") {
    if (inputs == kJetForces)
      model.update(IdentifyFossen<fossen::JetForceModel>(o, data, prepared, log));
    else if (inputs == kWaterjets)
      model.update(IdentifyFossen<fossen::WaterjetModel>(o, data, prepared, log));
    else if (inputs == kRudder)
      model.update(IdentifyFossen<fossen::RudderModel>(o, data, prepared, log));
    else
      model.update(IdentifyFossen<fossen::Odin3DofModel>(o, data, prepared, log));
  } else if (o.method == "nomoto") {
    const nomoto::NomotoFit fit =
        nomoto::FitNomoto(prepared, states[0], inputs[0], o.segment_s > 0 ? o.segment_s : 30.0);
    model["parameters"] = {{"K", fit.K}, {"T", fit.T}, {"delta0", fit.delta0}};
    model["equations"] = nomoto::NomotoEquations(fit, states[0], inputs[0]);
    model["nomoto"] = {
        {"parameter_sd", {{"K", fit.sd_K}, {"T", fit.sd_T}, {"delta0", fit.sd_delta0}}},
        {"equation_error",
         {{"K", fit.equation_error_K},
          {"T", fit.equation_error_T},
          {"delta0", fit.equation_error_delta0}}},
        {"converged", fit.converged},
        {"termination", fit.termination},
        {"notes", fit.notes}};
    for (const std::string& note : fit.notes) Log(log, note);
  } else if (o.method == "sindy") {
    // Regime features enter SINDy's library as linear columns named by DerivedVariable::Column.
    std::vector<std::string> library_inputs = inputs;
    for (const DerivedVariable& f : gpo.features) {
      prepared.data.Set(
          f.Column(), Expression::Parse(f.expression, "feature " + f.name).Evaluate(prepared.data));
      library_inputs.push_back(f.Column());
    }
    const sindy::SindyIdentification id = sindy::IdentifyWithSindy(
        prepared, states, variables, library_inputs, sindy::SindyOptions{});
    model["parameters"] = id.parameters;
    model["equations"] = id.equations;
    model["sindy"] = id.details;
    model["sindy"]["features"] = features_json;
  } else {
    const gp::GpIdentification gp = gp::IdentifyWithGp(
        prepared, states, variables, inputs, gpo,
        [&](const std::string& state, const gp::GenerationLog& g) {
          char line[200];
          std::snprintf(line, sizeof line,
                        "%s' generation %d: best r2 %.6f, size %zu, fitness %.6f, "
                        "%.3g node evaluations/s",
                        state.c_str(), g.generation, g.best_r2, g.best_size, g.best_fitness,
                        g.node_evals_per_second);
          Log(log, line);
        });
    const gp::GpOptions& so = gpo.search;
    model["parameters"] = gp.parameters;
    model["equations"] = gp.equations;
    const char* weight_fit =
        gpo.weight_fit == gp::WeightFit::kSimulation ? "simulation" : "equation";
    model["gp"] = {{"preset", o.preset},
                   {"operators", gp::OperatorList(so.functions)},
                   {"features", features_json},
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
                   {"fitness", o.fitness},
                   {"fit_rows", so.fit_rows},
                   {"node_evaluations", gp.node_evaluations},
                   {"equations", gp.details}};
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  model["train"] = {{"data", o.data_name}, {"samples", prepared.data.rows()}, {"seconds", seconds}};
  return model;
}

}  // namespace usvid
