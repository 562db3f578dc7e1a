// `sindy`: sparse regression on a library of terms (methods/sindy/sindy.h), registered in
// methods/method_list.h.
#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include "core/correlation_time.h"
#include "core/error.h"
#include "core/expression.h"
#include "core/parse_number.h"
#include "methods/channel_fit.h"
#include "methods/method.h"
#include "methods/regime_features.h"
#include "methods/sindy/sindy.h"
#include "methods/sindy/weak_form.h"
#include "simulation/segment_length.h"
#include "simulation/vessel_simulator.h"

namespace usvid {

namespace {

std::vector<OptionSpec> SindyOptionSpecs() {
  const sindy::SindyOptions d;
  const std::vector<double> grid = sindy::DefaultThresholds();
  return {
      NumberOption("threshold", std::nullopt, 0, kUnbounded,
                   "coefficient threshold on unit-RMS columns; none: chosen per state by "
                   "cross-validation over contiguous blocks among " +
                       std::to_string(grid.size()) + " values from " + FormatNumber(grid.front()) +
                       " to " + FormatNumber(grid.back())),
      NumberOption("ridge", d.ridge, 0, kUnbounded,
                   "relative ridge during thresholding, at least the squared relative noise of "
                   "the library's columns"),
      IntegerOption("folds", d.folds, 2, 1000, "contiguous-block folds that choose the threshold"),
      NumberOption("weak_window_s", std::nullopt, 0, kUnbounded,
                   "seconds: regress the weak (integral) form over overlapping windows of this "
                   "length, which takes no derivative of the data (for velocities that jump, "
                   "e.g. from GPS); 0: the derivatives; none: the derivatives, and where they "
                   "cut every term of an equation, the weak form over one hull length of travel "
                   "(a vessel with a length; else the e-folding time of the yaw rate's "
                   "autocorrelation), shortened to leave 10 windows a fold"),
      ListOption(
          "library", {"constant", "products", "abs", "rudder"},
          {"constant", "products", "abs", "inputs", "rudder"},
          "the candidate terms besides each variable and input: constant, products "
          "(x_i x_k of the variables), abs (|x_i| x_i), inputs (x_i u_j, u_j u_m and "
          "|u_j| u_j: a rudder's force with speed, a propeller's thrust), rudder (delta times "
          "|u| u, u n+ and n+ n+: the force of a rudder behind a propeller, whose wash "
          "reaches it when the propeller turns ahead, n+ = max(n, 0))"),
      RegimeFeaturesOption(kSindyFroudeHinges),
  };
}

sindy::SindyOptions SindyOptionsFor(const MethodOptions& o) {
  sindy::SindyOptions s;
  if (o.Has("threshold")) s.thresholds = {o.Number("threshold")};
  s.ridge = o.Number("ridge");
  s.folds = static_cast<int>(o.Integer("folds"));
  const std::vector<std::string> library = o.List("library");
  auto has = [&](const char* term) { return std::ranges::find(library, term) != library.end(); };
  s.library.constant = has("constant");
  s.library.products = has("products");
  s.library.abs_terms = has("abs");
  s.library.input_products = has("inputs");
  s.library.rudder_inflow = has("rudder");
  return s;
}

// An equation with no term is a failed fit, not a model "x' = 0": why every term of `state`
// was cut, from its details (the threshold given, or the held-out path: no term better than
// none, or none within one standard error of the best), and what to try: the weak form, or,
// when it was the weak form over `weak_window_s` windows already, other windows.
std::string EmptyEquationError(const std::string& state, const nlohmann::json& details, bool given,
                               double weak_window_s) {
  std::ostringstream s;
  s << "sindy: every term of " << state << "' was cut: ";
  const nlohmann::json& path = details.at("thresholds");
  if (given) {
    s << "the threshold " << FormatNumber(details.at("threshold").get<double>()) << " leaves none";
  } else {
    const nlohmann::json* least = &path.front();
    for (const nlohmann::json& p : path)
      if (p.at("heldout_mse").get<double>() < least->at("heldout_mse").get<double>()) least = &p;
    const double every = path.front().at("heldout_mse").get<double>();
    if (least->at("terms").get<int>() == 0)
      s << "no term predicts the held-out folds' " << state << "' better than none (held-out MSE "
        << FormatNumber(least->at("heldout_mse").get<double>()) << " with none, "
        << FormatNumber(every) << " with every term)";
    else
      s << "the one-standard-error rule chose the threshold "
        << FormatNumber(details.at("threshold").get<double>()) << ", and the least held-out MSE, "
        << FormatNumber(least->at("heldout_mse").get<double>()) << " with "
        << least->at("terms").get<int>() << " terms, is within one standard error of none";
  }
  if (weak_window_s > 0)
    s << "; this in the weak form over " << FormatNumber(std::round(weak_window_s * 10) / 10)
      << " s windows: try other windows (--weak-window-s: longer ones average more noise away, "
         "shorter ones follow faster dynamics), a smaller --threshold, or more data";
  else
    s << "; the derivative may be mostly noise at this record's precision: try the weak form "
         "(--weak-window-s, e.g. the time of one hull length of travel), a smaller --threshold, "
         "or more data";
  return s.str();
}

// The weak form's fallback window: one hull length of travel at the record's median speed (the
// time over which the vessel's state changes; docs/baselines.md#the-weak-form); without a vessel
// or a length, the time over which the record's own yaw rate changes: the e-folding time of r's
// autocorrelation (half its integrated correlation time, core/correlation_time.h; of the first
// state when r is not one). Shortened to leave 10 windows a fold; 0 when neither is known.
double WeakWindowSeconds(const Dataset& prepared, const IdentifyRequest& request,
                         const std::vector<std::string>& states, int folds) {
  double seconds = 0.0;
  if (!request.vessel.empty()) seconds = HullLengthSeconds(prepared, request.vessel.Info());
  if (!(seconds > 0) && !states.empty() && prepared.rows() > 8) {
    const bool has_r = std::ranges::find(states, "r") != states.end();
    const Eigen::VectorXd x = prepared[has_r ? "r" : states.front()];
    const double dt = prepared.duration() / static_cast<double>(prepared.rows() - 1);
    seconds = 0.5 * CorrelationTime(x, 1) * dt;
  }
  return seconds > 0 ? sindy::LongestWeakWindow(prepared.t(), seconds, 10L * folds) : 0.0;
}

// The first state whose every term was cut, or "".
std::string EmptyState(const sindy::SindyIdentification& id,
                       const std::vector<std::string>& states) {
  for (const std::string& state : states)
    if (id.details.at(state).at("terms").empty()) return state;
  return "";
}

// `state`'s equation in `id` replaced by the linear one: its derivative (or weak form) against the
// constant, the state itself and each input, by least squares (the threshold 0 cuts nothing), a
// first-order model every record supports: a rate that relaxes towards what the inputs hold.
// The held-out path of the thresholds, as the full library found it, stays in the details.
void FallBackToLinear(const ChannelFit& fit, const std::vector<std::string>& inputs,
                      sindy::SindyOptions options, const std::string& state,
                      sindy::SindyIdentification& id) {
  options.library = LibraryOptions{};
  options.library.constant = true;
  options.library.products = options.library.abs_terms = false;
  options.library.input_products = options.library.rudder_inflow = false;
  options.thresholds = {0.0};
  const sindy::SindyIdentification linear =
      sindy::IdentifyWithSindy(fit.prepared, {state}, {state}, inputs, options);
  id.equations[state] = linear.equations.at(state);
  for (const auto& [name, value] : linear.parameters.items()) id.parameters[name] = value;
  nlohmann::json details = linear.details.at(state);
  details["thresholds"] = id.details.at(state).at("thresholds");
  details["fallback"] = "linear: the held-out folds supported no term of the library";
  id.details[state] = details;
}

nlohmann::json IdentifySindyModel(const Dataset& data, const IdentifyRequest& request,
                                  const MethodOptions& o, const Logger& log) {
  sindy::SindyOptions options = SindyOptionsFor(o);
  ChannelFit fit = PrepareChannelFit(data, request, DefaultChannels(request, data), log);
  const double froude_per_speed =
      request.vessel.empty() ? 0.0 : request.vessel.Simulator().FroudeNumber(1.0).value_or(0.0);
  const std::vector<DerivedVariable> features =
      RegimeFeatures(o.Text("features"), froude_per_speed, fit.prepared.data, kSindyFroudeHinges);
  // Regime features enter SINDy's library as linear columns named by DerivedVariable::Column.
  std::vector<std::string> library_inputs = fit.channels.inputs;
  nlohmann::json features_json = nlohmann::json::object();  // name -> expression
  for (const DerivedVariable& f : features) {
    fit.prepared.data.Set(
        f.Column(),
        Expression::Parse(f.expression, "feature " + f.name).Evaluate(fit.prepared.data));
    library_inputs.push_back(f.Column());
    features_json[f.name] = f.expression;
  }
  const auto identify = [&] {
    return sindy::IdentifyWithSindy(fit.prepared, fit.channels.states, fit.channels.variables,
                                    library_inputs, options);
  };
  const bool given = o.Has("weak_window_s");
  if (given) options.weak_window_s = o.Number("weak_window_s");
  sindy::SindyIdentification id = identify();
  std::string empty = EmptyState(id, fit.channels.states);
  // The derivatives could not support an equation: the weak form, which takes none.
  if (!given && !empty.empty()) {
    options.weak_window_s =
        WeakWindowSeconds(fit.prepared.data, request, fit.channels.states, options.folds);
    if (options.weak_window_s > 0) {
      Log(log, "sindy: every term of " + empty + "' was cut from the derivatives; the weak form " +
                   "over " + FormatNumber(std::round(options.weak_window_s * 10) / 10) +
                   " s windows instead");
      id = identify();
      empty = EmptyState(id, fit.channels.states);
    }
  }
  // Neither form supports a term of `empty` by held-out error: a threshold or window the user
  // gave is theirs to change (an error), but at the defaults the equation falls back to the
  // linear one (FallBackToLinear) rather than failing the fit, with a warning.
  nlohmann::json warnings = nlohmann::json::array();
  std::set<std::string> linear;  // once each: a state whose linear equation is 0 too fails
  while (!empty.empty() && !o.Has("threshold") && !given && linear.insert(empty).second) {
    warnings.push_back(
        EmptyEquationError(empty, id.details.at(empty), false, options.weak_window_s) +
        ". Kept instead: " + empty + "' linear in " + empty +
        " and the inputs, with a constant, "
        "by least squares, no term cut");
    Log(log, "sindy: warning: every term of " + empty + "' was cut; its linear equation kept");
    FallBackToLinear(fit, library_inputs, options, empty, id);
    empty = EmptyState(id, fit.channels.states);
  }
  if (!empty.empty())
    throw InputError(
        EmptyEquationError(empty, id.details.at(empty), o.Has("threshold"), options.weak_window_s));
  if (!warnings.empty()) fit.model["warnings"] = warnings;
  fit.model["parameters"] = id.parameters;
  fit.model["equations"] = id.equations;
  fit.model["sindy"] = id.details;
  fit.model["sindy"]["features"] = features_json;
  SetTrain(fit, request);
  return fit.model;
}

}  // namespace

Method SindyMethod() {
  Method m;
  m.name = std::string(sindy::kMethodName);
  m.summary = "sparse regression on a library of terms (STRidge)";
  m.options = SindyOptionSpecs();
  m.identify = IdentifySindyModel;
  m.channel_inputs = true;
  m.any_inputs = true;
  return m;
}

}  // namespace usvid
