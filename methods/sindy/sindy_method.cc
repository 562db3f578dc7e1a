// `sindy`: sparse regression on a library of terms (methods/sindy/sindy.h), registered in
// methods/method_list.h.
#include <algorithm>
#include <cmath>
#include <sstream>

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
                   "(a vessel with a length; shortened to leave 10 windows a fold)"),
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
std::string EmptyEquationError(const std::string& state, const nlohmann::json& details,
                               bool given, double weak_window_s) {
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
// time over which the vessel's state changes; docs/baselines.md#the-weak-form), shortened to
// leave 10 windows a fold; 0 for a vessel without a length, or no vessel.
double HullWindowSeconds(const Dataset& prepared, const IdentifyRequest& request, int folds) {
  if (request.vessel.empty()) return 0.0;
  const double hull = HullLengthSeconds(prepared, FindVessel(request.vessel).Info());
  return hull > 0 ? sindy::LongestWeakWindow(prepared.t(), hull, 10L * folds) : 0.0;
}

// The first state whose every term was cut, or "".
std::string EmptyState(const sindy::SindyIdentification& id,
                       const std::vector<std::string>& states) {
  for (const std::string& state : states)
    if (id.details.at(state).at("terms").empty()) return state;
  return "";
}

nlohmann::json IdentifySindyModel(const Dataset& data, const IdentifyRequest& request,
                                  const MethodOptions& o, const Logger& log) {
  sindy::SindyOptions options = SindyOptionsFor(o);
  ChannelFit fit = PrepareChannelFit(data, request, DefaultChannels(request), log);
  const double froude_per_speed =
      request.vessel.empty() ? 0.0 : FindVessel(request.vessel).FroudeNumber(1.0).value_or(0.0);
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
    options.weak_window_s = HullWindowSeconds(fit.prepared.data, request, options.folds);
    if (options.weak_window_s > 0) {
      Log(log, "sindy: every term of " + empty + "' was cut from the derivatives; the weak form " +
                   "over " + FormatNumber(std::round(options.weak_window_s * 10) / 10) +
                   " s windows instead");
      id = identify();
      empty = EmptyState(id, fit.channels.states);
    }
  }
  if (!empty.empty())
    throw InputError(EmptyEquationError(empty, id.details.at(empty), o.Has("threshold"),
                                        options.weak_window_s));
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
