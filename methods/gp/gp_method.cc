// `gp`: GP-SR with orthogonal least squares (methods/gp/gp_identify.h), registered in
// methods/method_list.h.
#include <algorithm>
#include <cstdio>

#include "core/error.h"
#include "core/parse_number.h"
#include "methods/channel_fit.h"
#include "methods/gp/gp_identify.h"
#include "methods/gp/term_selection.h"
#include "methods/method.h"
#include "methods/regime_features.h"
#include "simulation/vessel_simulator.h"

namespace usvid {
namespace {

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
  if (std::string error; !s.IsValid(&error)) {
    // IsValid names the field (max_depth ...); the command line spells it --max-depth.
    const size_t space = error.find(' ');
    std::string flag = error.substr(0, space);
    std::replace(flag.begin(), flag.end(), '_', '-');
    throw InputError("--" + flag + ":" + error.substr(space));
  }
  if (!(g.validation_fraction >= 0 && g.validation_fraction <= 0.5))
    throw InputError(
        "--validation-fraction: must be in [0, 0.5] (the share of the record kept "
        "to choose the model by simulation; 0: none)");
  if (!(g.horizon_s > 0 && g.horizon_s <= 600))
    throw InputError("--horizon: must be in (0, 600] seconds, got " + FormatNumber(g.horizon_s));
  return g;
}

nlohmann::json GpDetails(const IdentifyRequest& o, const gp::GpIdentifyOptions& gpo,
                         const gp::GpIdentification& gp, const nlohmann::json& features) {
  const gp::GpOptions& so = gpo.search;
  const char* weight_fit = gpo.weight_fit == gp::WeightFit::kSimulation ? "simulation" : "equation";
  return {{"preset", o.preset},
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
          {"fitness", o.fitness},
          {"fit_rows", so.fit_rows},
          {"node_evaluations", gp.node_evaluations},
          {"equations", gp.details}};
}

nlohmann::json IdentifyGpModel(const Dataset& data, const IdentifyRequest& o, const Logger& log) {
  gp::GpIdentifyOptions gpo = GpOptionsFor(o);
  ChannelFit fit = PrepareChannelFit(data, o, DefaultChannels(o), log);
  const double froude_per_speed =
      o.vessel.empty() ? 0.0 : FindVessel(o.vessel).FroudeNumber(1.0).value_or(0.0);
  gpo.features = RegimeFeatures(o.features, froude_per_speed, fit.prepared.data, kGpFroudeHinges);
  // Term completion where it was measured to help: on records with regime features (odin-hs's
  // zig-zag, docs/gp.md); on KVLCC2's single zig-zag it cost GP the heading.
  gpo.complete_terms = !gpo.features.empty();
  // A hull that crosses regimes holds its speed where the resistance is steep (the knee of
  // odin-hs's hump): a surge equation a few percent off there shows over 30 s, not over 10 s
  // (docs/gp.md).
  if (gpo.complete_terms && !o.horizon_s) gpo.horizon_s = kRegimeHorizonS;
  if (gpo.complete_terms && o.features != "froude")
    gpo.completion_features =
        RegimeFeatures(o.features, froude_per_speed, fit.prepared.data, kSindyFroudeHinges);
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
  SetTrain(fit, o);
  return fit.model;
}

}  // namespace

Method GpMethod() {
  Method m;
  m.name = std::string(gp::kMethodName);
  m.summary = "GP-SR with orthogonal least squares";
  m.identify = IdentifyGpModel;
  m.channel_inputs = true;
  m.regime_features = true;
  m.seeded = true;
  m.label_option = "operators";
  m.relative_cost = 30.0;  // the search, the selection's simulations and the weights' refit
  return m;
}

}  // namespace usvid
