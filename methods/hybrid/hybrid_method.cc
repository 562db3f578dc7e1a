// `hybrid`: refit plus the missing terms its residual proposes and held-out simulation keeps
// (methods/hybrid/hybrid.h), registered in methods/method_list.h.
#include <cmath>

#include "core/error.h"
#include "effects/effect.h"
#include "methods/hybrid/hybrid.h"
#include "methods/method.h"
#include "methods/refit/refit_model_json.h"
#include "simulation/vessel_simulator.h"

namespace usvid {
namespace {

// A free-run error, or "diverged".
nlohmann::json FiniteOr(double error) {
  return std::isfinite(error) ? nlohmann::json(error) : nlohmann::json("diverged");
}

// hybrid: the vessel refitted with the missing terms its residual proposes and held-out
// simulation keeps (methods/hybrid/hybrid.h); a vessel model whose effects are those terms.
nlohmann::json IdentifyHybridModel(const Dataset& data, const IdentifyRequest& o,
                                   const MethodOptions& options, const Logger& log) {
  if (o.vessel.empty()) throw InputError("--method hybrid: needs --vessel");
  const VesselInfo& info = o.vessel.Info();
  hybrid::HybridOptions ho;
  ho.refit = RefitOptionsFor(options);
  ho.refit.threads = o.threads > 0 ? o.threads : 1;  // proposals in parallel, each one thread
  ho.max_terms = static_cast<int>(options.Integer("max_terms"));
  ho.search_rows = options.Integer("search_rows");
  ho.set_aside_cosine = options.Number("set_aside_cosine");
  const hybrid::HybridResult h = hybrid::IdentifyHybrid(
      o.vessel, data, o.start_params.empty() ? info.default_params : o.start_params, ho);
  nlohmann::json proposals = nlohmann::json::array(), rounds = nlohmann::json::array();
  for (size_t i = 0; i < h.proposals.size(); ++i) {
    nlohmann::json j = EffectToJson(h.proposals[i].term);
    j["err"] = h.proposals[i].err;
    if (!h.proposal_shapes[i].parameter.empty())
      j["closest_free_coefficient"] = {{"parameter", h.proposal_shapes[i].parameter},
                                       {"cosine", h.proposal_shapes[i].cosine}};
    proposals.push_back(j);
  }
  nlohmann::json set_aside = nlohmann::json::array();
  for (const auto& [p, shape] : h.set_aside) {
    nlohmann::json j = EffectToJson(p.term);
    j["err"] = p.err;
    j["closest_free_coefficient"] = {{"parameter", shape.parameter}, {"cosine", shape.cosine}};
    set_aside.push_back(j);
  }
  for (const hybrid::SelectionRound& r : h.rounds) {
    nlohmann::json errors = nlohmann::json::object();
    for (size_t j = 0; j < r.heldout_error.size(); ++j)
      if (std::isfinite(r.heldout_error[j]))
        errors[EffectLabel(h.proposals[j].term)] = r.heldout_error[j];
    nlohmann::json free_runs = nlohmann::json::object();
    for (size_t j = 0; j < r.free_run_error.size(); ++j)
      if (std::isfinite(r.heldout_error[j]))
        free_runs[EffectLabel(h.proposals[j].term)] = FiniteOr(r.free_run_error[j]);
    rounds.push_back({{"heldout_error", errors},
                      {"free_run_error", free_runs},
                      {"likelihood_ratio", r.likelihood_ratio},
                      {"chosen", r.chosen >= 0 ? EffectLabel(h.proposals[r.chosen].term)
                                               : std::string("none")}});
  }
  nlohmann::json effects = nlohmann::json::array();
  for (const Effect& e : h.fit.terms) effects.push_back(EffectToJson(e));
  Log(log, "hybrid: " + std::to_string(h.fit.terms.size()) + " of " +
               std::to_string(h.proposals.size()) + " proposed terms kept; held-out error " +
               std::to_string(h.vessel_heldout_error) + " -> " + std::to_string(h.heldout_error));
  return {{"method", o.method},
          {"vessel", o.vessel.Name()},
          {"states", h.fit.channels},
          {"inputs", info.inputs},
          {"parameters", RefitParameters(h.fit)},
          {"effects", effects},
          {std::string(kRefitMethodName), RefitDetails(h.fit, ho.refit.prior_sd)},
          {"hybrid",
           {{"heldout_fraction", ho.heldout},
            {"proposals", proposals},
            {"set_aside", set_aside},
            {"set_aside_cosine", ho.set_aside_cosine},
            {"rounds", rounds},
            {"vessel_heldout_error", h.vessel_heldout_error},
            {"effective_samples", h.effective_samples},
            {"critical_ratio", ho.critical_ratio},
            {"heldout_error", h.heldout_error},
            {"vessel_free_run_error", FiniteOr(h.vessel_free_run_error)},
            {"free_run_error", FiniteOr(h.free_run_error)}}},
          {"train", {{"data", o.data_name}, {"samples", data.rows()}, {"seconds", h.seconds}}}};
}

}  // namespace

Method HybridMethod() {
  Method m;
  m.name = std::string(hybrid::kMethodName);
  m.summary = "refit plus the missing terms its residual proposes and held-out simulation keeps";
  m.options = RefitOptionSpecs();
  m.options.push_back(IntegerOption("max_terms", hybrid::HybridOptions{}.max_terms, 0,
                                    kMaxRefitTerms, "most missing terms to add"));
  m.options.push_back(IntegerOption(
      "search_rows", hybrid::HybridOptions{}.search_rows, 0, kUnbounded,
      "the most rows each proposed term's fit and score use (0: half of fit_rows); the final "
      "fit takes fit_rows"));
  m.options.push_back(NumberOption(
      "set_aside_cosine", hybrid::HybridOptions{}.set_aside_cosine, 0, 1,
      "set aside a proposed term whose shape is at least this close (|cos|) to a freed "
      "coefficient's: that coefficient past its prior, not a missing term (0: keep all)"));
  m.identify = IdentifyHybridModel;
  // A refit per proposed term, then the final one: on Esso Osaka's eight runs 150 s against the
  // refit's 14 and GP's 18 (real suite, 2026-12-02).
  m.relative_cost = 250.0;
  return m;
}

}  // namespace usvid
