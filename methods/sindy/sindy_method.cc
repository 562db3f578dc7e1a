// `sindy`: sparse regression of the derivatives on a library of terms (methods/sindy/sindy.h),
// registered in methods/method_list.h.
#include "core/expression.h"
#include "methods/channel_fit.h"
#include "methods/method.h"
#include "methods/regime_features.h"
#include "methods/sindy/sindy.h"
#include "simulation/vessel_simulator.h"

namespace usvid {
namespace {

nlohmann::json IdentifySindyModel(const Dataset& data, const IdentifyRequest& o,
                                  const Logger& log) {
  ChannelFit fit = PrepareChannelFit(data, o, DefaultChannels(o), log);
  const double froude_per_speed =
      o.vessel.empty() ? 0.0 : FindVessel(o.vessel).FroudeNumber(1.0).value_or(0.0);
  const std::vector<DerivedVariable> features =
      RegimeFeatures(o.features, froude_per_speed, fit.prepared.data, kSindyFroudeHinges);
  // Regime features enter SINDy's library as linear columns named by DerivedVariable::Column.
  std::vector<std::string> library_inputs = fit.channels.inputs;
  nlohmann::json features_json = nlohmann::json::object();  // name -> expression
  for (const DerivedVariable& f : features) {
    fit.prepared.data.Set(f.Column(), Expression::Parse(f.expression, "feature " + f.name)
                                          .Evaluate(fit.prepared.data));
    library_inputs.push_back(f.Column());
    features_json[f.name] = f.expression;
  }
  const sindy::SindyIdentification id =
      sindy::IdentifyWithSindy(fit.prepared, fit.channels.states, fit.channels.variables,
                               library_inputs, sindy::SindyOptions{});
  fit.model["parameters"] = id.parameters;
  fit.model["equations"] = id.equations;
  fit.model["sindy"] = id.details;
  fit.model["sindy"]["features"] = features_json;
  SetTrain(fit, o);
  return fit.model;
}

}  // namespace

Method SindyMethod() {
  Method m;
  m.name = std::string(sindy::kMethodName);
  m.summary = "sparse regression on a library of terms (STRidge)";
  m.identify = IdentifySindyModel;
  m.channel_inputs = true;
  m.regime_features = true;
  return m;
}

}  // namespace usvid
