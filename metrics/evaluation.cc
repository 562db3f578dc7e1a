#include "metrics/evaluation.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/derived_channels.h"
#include "core/expression.h"
#include "core/model_view.h"
#include "metrics/fit_metrics.h"
#include "preprocessing/pipeline.h"
#include "preprocessing/waterjet_forces.h"
#include "simulation/vessel_ref.h"
#include "simulation/vessel_simulator.h"
#include "simulators/vessel.h"

namespace usvid {
namespace {

// The time until the RMS of the dynamic channels' errors, each in units of its standard
// deviation in the record, first exceeds kValidPredictionError (the record's length if never).
double ValidPredictionTime(const Dataset& data, const FreeRun& run) {
  std::vector<std::pair<const Eigen::VectorXd*, const Eigen::VectorXd*>> pairs;
  std::vector<double> sd;
  for (const std::string& c : run.channels) {
    if (IsPositionOrHeading(c) || c == "x" || !data.Has(c)) continue;
    const Eigen::VectorXd& m = data[c];
    const double mean = m.mean(), s = std::sqrt((m.array() - mean).square().mean());
    if (!(s > 0)) continue;
    pairs.push_back({&m, &run.simulated[c]});
    sd.push_back(s);
  }
  if (pairs.empty()) return NAN;
  for (Eigen::Index k = 0; k < data.rows(); ++k) {
    double sum = 0.0;
    for (size_t i = 0; i < pairs.size(); ++i)
      sum += std::pow(((*pairs[i].second)(k) - (*pairs[i].first)(k)) / sd[i], 2);
    if (!(std::sqrt(sum / pairs.size()) <= kValidPredictionError)) return data.t()(k) - data.t()(0);
  }
  return data.duration();
}

// A model identified on the jets' forces is driven by them here too (unless the data carry
// them already, as `usvid preprocess --forces waterjet` writes them).
void AddModelForces(const nlohmann::json& model, Dataset& data) {
  const std::string forces = ModelView(model).Forces();
  if (!forces.empty() && !data.Has("tau_x")) AddForces(data, forces);
}

// One-step derivative R^2: each equation at the measured states against the data's
// derivatives (default estimator, inputs shifted by the model's delay). Empty for a vessel
// model, or when the data lack a variable or input of the equations.
std::map<std::string, double> DerivativeR2(const nlohmann::json& model, const Dataset& data) {
  std::map<std::string, double> r2;
  const ModelView view(model);
  const bool has_equations = view.HasEquations();  // else a vessel model
  const std::vector<std::string> inputs = view.Inputs();
  const std::vector<std::string> variables = view.Variables().value_or(view.EquationStates());
  bool can_differentiate = has_equations && !inputs.empty();
  for (const auto& names : {variables, inputs})
    for (const std::string& n : names) can_differentiate = can_differentiate && data.Has(n);
  if (can_differentiate) {
    PreprocessOptions pre;
    pre.delay_s = view.DelaySeconds();
    const PreparedData prepared = Preprocess(data, variables, inputs, pre);
    for (const auto& [state, text] : view.Equations()) {
      const Expression expr = Expression::Parse(text, "model: " + state);
      r2[state] = RSquared(prepared.data[state + "_dot"], expr.Evaluate(prepared.data));
    }
  }
  return r2;
}

// k-step-ahead: from every k-th measured state, k steps of the model; the error at the end.
std::map<std::string, std::map<std::string, double>> KStepNrmse(const nlohmann::json& model,
                                                                const Dataset& data) {
  std::map<std::string, std::map<std::string, double>> k_step;
  for (const int k : {10, 40}) {
    if (data.rows() < 3 * k) continue;
    std::map<std::string, std::vector<double>> measured, predicted;
    for (Eigen::Index start = 0; start + k < data.rows(); start += k) {
      const Dataset window = data.Rows(start, k + 1);
      const FreeRun run = FreeRunModel(model, window);
      for (const std::string& c : run.channels)
        if (data.Has(c)) {
          measured[c].push_back(window[c](k));
          predicted[c].push_back(run.simulated[c](k));
        }
    }
    std::map<std::string, double> per;
    for (const auto& [c, m] : measured) {
      const Eigen::VectorXd a = Eigen::Map<const Eigen::VectorXd>(m.data(), m.size());
      const Eigen::VectorXd b = Eigen::Map<const Eigen::VectorXd>(predicted[c].data(), m.size());
      per[c] = ScoreChannel(a, b).nrmse;
    }
    k_step[std::to_string(k)] = per;
  }
  return k_step;
}

// The fit % of each channel over the whole record ("all", from `channels`' scores) and over
// each horizon of kHorizonsS shorter than the record.
std::map<std::string, std::map<std::string, double>> HorizonFits(
    const nlohmann::json& model, const Dataset& data,
    const std::map<std::string, ChannelScore>& channels) {
  std::map<std::string, std::map<std::string, double>> horizons = {{"all", {}}};
  for (const auto& [c, s] : channels) horizons["all"][c] = s.fit_percent;
  for (const double h : kHorizonsS)
    if (h < data.duration()) horizons[HorizonKey(h)] = HorizonFit(model, data, h);
  return horizons;
}

// The measured speed over ground: U, else from u and v, else empty.
Eigen::VectorXd MeasuredSpeed(const Dataset& data) {
  Eigen::VectorXd speed;
  if (data.Has("U")) {
    speed = data["U"];
  } else if (data.Has("u") && data.Has("v")) {
    speed = (data["u"].array().square() + data["v"].array().square()).sqrt().matrix();
  }
  return speed;
}

// The hull length: the model's "length_m", else its vessel's, else Odin's 10.5 m.
double HullLength(const nlohmann::json& model) {
  double length = 10.5;
  const ModelView view(model);
  if (const std::string vessel = view.Vessel(); !vessel.empty()) {
    const std::vector<std::string> known = VesselNames();
    if (std::ranges::find(known, vessel) != known.end() || IsVesselFile(vessel))
      if (const double l = VesselRef(vessel).Info().length_m; l > 0) length = l;
  }
  return view.LengthM().value_or(length);
}

// Per speed regime (by Froude number on the hull length), over the rows measured in it: each
// scored channel's scores, for regimes with at least 10 rows.
std::map<std::string, Scores::Regime> RegimeScores(
    const Eigen::VectorXd& speed, double length, const Dataset& data, const FreeRun& run,
    const std::map<std::string, ChannelScore>& channels) {
  const Eigen::ArrayXd fn = speed.array() / std::sqrt(9.81 * length);
  const std::pair<const char*, std::pair<double, double>> regimes[] = {
      {"displacement", {-INFINITY, 0.4}},
      {"semi-displacement", {0.4, 1.1}},
      {"planing", {1.1, INFINITY}}};
  std::map<std::string, Scores::Regime> by_regime;
  for (const auto& [name, range] : regimes) {
    const Eigen::Array<bool, Eigen::Dynamic, 1> in = fn >= range.first && fn < range.second;
    if (in.count() < 10) continue;
    Scores::Regime& regime = by_regime[name];
    regime.samples = in.count();
    for (const auto& [c, _] : channels) {
      const Eigen::VectorXd m = in.select(data[c].array(), NAN).matrix();
      regime.channels[c] = ScoreChannel(m, run.simulated[c]);
    }
  }
  return by_regime;
}

}  // namespace

std::string HorizonKey(double horizon_s) {
  return std::isfinite(horizon_s) ? std::to_string(std::lround(horizon_s)) : "all";
}

std::map<std::string, double> HorizonFit(const nlohmann::json& model, const Dataset& data,
                                         double horizon_s) {
  std::vector<Eigen::Index> starts;
  const Eigen::VectorXd& t = data.t();
  for (Eigen::Index start = 0; start < data.rows();) {
    starts.push_back(start);
    Eigen::Index end = start + 1;
    while (end < data.rows() && t(end) < t(start) + horizon_s - 1e-9) ++end;
    start = end;
  }
  std::map<std::string, double> fit;
  if (starts.empty()) return fit;
  const FreeRun run = FreeRunWindows(model, data, starts);
  for (const std::string& c : run.channels)
    if (data.Has(c)) fit[c] = ScoreChannel(data[c], run.simulated[c]).fit_percent;
  return fit;
}

nlohmann::json Scores::ToJson() const {
  nlohmann::json channels_json = nlohmann::json::object();
  for (const auto& [c, score] : channels) channels_json[c] = score.ToJson();
  nlohmann::json m = {{"channels", channels_json},
                      {"derivative_r2", derivative_r2},
                      {"diverged", diverged},
                      {"samples", samples},
                      {"seconds", seconds},
                      {"k_step_nrmse", k_step_nrmse},
                      {"horizon_fit_percent", horizon_fit_percent}};
  if (derivative_r2.empty()) m["derivative_r2"] = nlohmann::json::object();
  if (k_step_nrmse.empty()) m["k_step_nrmse"] = nlohmann::json::object();
  if (valid_prediction_s) m["valid_prediction_s"] = *valid_prediction_s;
  // Flat per-channel fields too, as docs/data.md#metricsjson lists them per state channel.
  for (const auto& [c, score] : channels) m[c] = score.ToJson();
  if (diverged) {
    m["diverged_at_s"] = diverged_at_s;
    m["diverged_channel"] = diverged_channel;
  }
  if (regimes) {
    nlohmann::json by_regime = nlohmann::json::object();
    for (const auto& [name, regime] : *regimes) {
      nlohmann::json r = {{"samples", regime.samples}};
      for (const auto& [c, score] : regime.channels) r[c] = score.ToJson();
      by_regime[name] = r;
    }
    m["regimes"] = by_regime;
  }
  if (position_drift_m) m["position_drift_m"] = *position_drift_m;
  return m;
}

Evaluation EvaluateModel(const nlohmann::json& model, const Dataset& recorded,
                         EvaluationScope scope) {
  Dataset data = recorded;
  AddDerivedChannels(data);  // U, chi (2-DOF models), wind_u, wind_v
  AddModelForces(model, data);
  Evaluation e;
  e.run = FreeRunModel(model, data);
  if (scope == EvaluationScope::kFreeRunOnly) return e;
  Scores& s = e.scores;
  for (const std::string& c : e.run.channels)
    if (data.Has(c)) s.channels[c] = ScoreChannel(data[c], e.run.simulated[c]);
  s.derivative_r2 = DerivativeR2(model, data);
  s.diverged = e.run.diverged;
  s.diverged_at_s = e.run.diverged_at_s;
  s.diverged_channel = e.run.diverged_channel;
  s.samples = data.rows();
  s.seconds = data.duration();
  if (scope == EvaluationScope::kAll) s.k_step_nrmse = KStepNrmse(model, data);
  s.horizon_fit_percent = HorizonFits(model, data, s.channels);
  if (const double vpt = ValidPredictionTime(data, e.run); std::isfinite(vpt))
    s.valid_prediction_s = vpt;
  // Per speed regime, over the rows measured in it.
  const Eigen::VectorXd speed = MeasuredSpeed(data);
  if (speed.size() > 0) s.regimes = RegimeScores(speed, HullLength(model), data, e.run, s.channels);
  if (data.Has("north") && data.Has("east") && e.run.simulated.Has("north")) {
    const Eigen::Index last = data.rows() - 1;
    s.position_drift_m = std::hypot(data["north"](last) - e.run.simulated["north"](last),
                                    data["east"](last) - e.run.simulated["east"](last));
  }
  e.metrics = s.ToJson();
  return e;
}

}  // namespace usvid
