#include "diagnosis/diagnosis_json.h"

#include <cmath>

#include "methods/nominal/nominal.h"

namespace usvid::diagnosis {
namespace {

// Finite numbers only: a table must never hold NaN (null where there is no number).
nlohmann::json Number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); }

// An uncertainty to three significant digits: SuiteSparse's QR inside ceres::Covariance may
// round differently from run to run in the last digits.
double ThreeDigits(double v) {
  if (v == 0.0 || !std::isfinite(v)) return v;
  const double e = std::pow(10.0, std::floor(std::log10(std::abs(v))) - 2);
  return std::round(v / e) * e;
}

nlohmann::json Fits(const FitPercent& fit) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [channel, value] : fit) j[channel] = Number(value);
  return j;
}

nlohmann::json Residual(const ChannelResidual& r) {
  nlohmann::json inputs = nlohmann::json::array();
  for (const InputCorrelation& c : r.inputs)
    inputs.push_back(
        {{"input", c.input}, {"lag_s", Number(c.lag_s)}, {"correlation", Number(c.correlation)}});
  nlohmann::json regressors = nlohmann::json::object();
  for (const auto& [name, value] : r.regressors) regressors[name] = Number(value);
  return {{"free_run_fit_percent", Number(r.free_run_fit_percent)},
          {"segment_fit_percent", Number(r.segment_fit_percent)},
          {"bias", Number(r.bias)},
          {"drift_per_s", Number(r.drift_per_s)},
          {"lag_s", Number(r.lag_s)},
          {"input_correlation", inputs},
          {"regressor_correlation", regressors}};
}

nlohmann::json Effects(const std::vector<Effect>& effects) {
  nlohmann::json j = nlohmann::json::array();
  for (const Effect& e : effects) j.push_back(EffectToJson(e));
  return j;
}

// The effects of the extended model: the nominal's own, then the causes in the order named.
std::vector<Effect> ExtendedEffects(const Diagnosis& d) {
  std::vector<Effect> all = d.base_effects;
  auto put = [&all](const Effect& e) {
    std::erase_if(all, [&e](const Effect& a) { return a.kind == e.kind; });
    all.push_back(e);
  };
  if (d.cause_effect) put(*d.cause_effect);
  for (const FurtherCause& f : d.further_causes) put(f.effect);
  return all;
}

// Where an effect acts, beside its sizes: the inputs of an effect on some inputs only, the state
// and term of a missing term (docs/data.md#diagnosisjson: "inputs", "state", "term").
void AddWhere(const Effect& e, nlohmann::json& j) {
  if (!e.inputs.empty()) j["inputs"] = e.inputs;
  if (e.kind == EffectKind::kMissingTerm) {
    j["state"] = e.state;
    j["term"] = e.term;
  }
}

}  // namespace

nlohmann::json DiagnosisToJson(const Diagnosis& d) {
  nlohmann::json j;
  j["vessel"] = d.vessel;
  j["data"] = d.source;
  j["split"] = {{"train_s", d.train_s},
                {"fit_s", d.fit_s},
                {"heldout_s", d.heldout_s},
                {"segment_s", d.segment_s},
                {"scored_channels", d.channels}};
  j[std::string(kNominalMethodName)] = {
      {"fit_percent", Fits(d.nominal_fit_percent)},
      {"heldout_fit_percent", Fits(d.nominal_fit_percent)},
      {"free_run_fit_percent", Fits(d.nominal_free_run_fit_percent)},
      {"heldout_error", Number(d.nominal_error)},
      {"noise_floor_error", Number(d.noise_floor)},
      {"correlation_time_samples", Number(d.correlation_time)},
      {"effective_samples", Number(d.effective_samples)},
      {"effects", Effects(d.base_effects)}};
  nlohmann::json residuals = nlohmann::json::object();
  for (const ChannelResidual& r : d.residuals) residuals[r.channel] = Residual(r);
  j["residuals"] = residuals;
  j["cause"] = d.cause;
  nlohmann::json candidates = nlohmann::json::array();
  for (const Candidate& c : d.candidates) {
    nlohmann::json parameters = nlohmann::json::object();
    for (const auto& [name, value] : c.fit.effect.parameters) parameters[name] = Number(value);
    nlohmann::json sd = nlohmann::json::object();
    size_t i = 0;
    for (const auto& [name, _] : c.fit.effect.parameters)
      if (i < c.fit.sd.size()) sd[name] = Number(ThreeDigits(c.fit.sd[i++]));
    nlohmann::json candidate = {{"effect", c.fit.effect.name()},
                                {"parameters", parameters},
                                {"parameter_sd", sd},
                                {"heldout_fit_percent", Fits(c.heldout_fit_percent)},
                                {"heldout_error", Number(c.heldout_error)},
                                {"explained", Number(c.explained)},
                                {"likelihood_ratio", Number(c.likelihood_ratio)},
                                {"indistinguishable_from", c.alike},
                                {"score", Number(c.score)},
                                {"train_error", Number(c.fit.train_cost)},
                                {"optimiser", c.fit.message},
                                {"seconds", Number(c.seconds)}};
    AddWhere(c.fit.effect, candidate);
    candidates.push_back(std::move(candidate));
  }
  j["candidates"] = candidates;
  nlohmann::json further = nlohmann::json::array(), causes = nlohmann::json::array();
  if (d.cause_effect) causes.push_back(d.cause);
  for (const FurtherCause& f : d.further_causes) {
    causes.push_back(f.effect.name());
    nlohmann::json cause = {{"effect", f.effect.name()},
                            {"parameters", f.effect.parameters},
                            {"likelihood_ratio", Number(f.likelihood_ratio)},
                            {"explained", Number(f.explained)},
                            {"heldout_error_before", Number(f.error_before)},
                            {"heldout_error_after", Number(f.error_after)},
                            {"indistinguishable_from", f.alike}};
    AddWhere(f.effect, cause);
    further.push_back(std::move(cause));
  }
  j["causes"] = causes;
  j["further_causes"] = further;
  j["extended"] = {{"effect", d.cause_effect ? EffectToJson(*d.cause_effect) : nlohmann::json()},
                   {"effects", Effects(ExtendedEffects(d))},
                   {"heldout_fit_percent", Fits(d.extended_fit_percent)},
                   {"heldout_error", Number(d.extended_error)}};
  j["gain"] = {{"heldout_error_reduction", Number(d.heldout_error_reduction)}};
  nlohmann::json discovered = nlohmann::json::array();
  for (const DiscoveredTerms& t : d.discovered)
    discovered.push_back({{"state", t.state},
                          {"missing_derivative", t.expression},
                          {"method", t.method},
                          {"heldout_r2", Number(t.heldout_r2)}});
  j["unexplained_residual"] = d.unexplained;
  j["discovered"] = discovered;
  j["seconds"] = Number(d.seconds);
  return j;
}

nlohmann::json ExtendedModelJson(const Diagnosis& d) {
  nlohmann::json parameters = nlohmann::json::object();
  for (size_t i = 0; i < d.params.size(); ++i) parameters[d.param_names[i]] = d.params[i];
  const nlohmann::json effects = Effects(ExtendedEffects(d));
  return {{"method", "diagnose"},
          {"vessel", d.vessel},
          {"parameters", parameters},
          {"effects", effects},
          {"train", {{"data", d.source}, {"seconds", d.train_s}}},
          {"heldout_fit_percent",
           {{std::string(kNominalMethodName), Fits(d.nominal_fit_percent)},
            {"extended", Fits(d.extended_fit_percent)}}}};
}

}  // namespace usvid::diagnosis
