// `lti`: each derivative linear in the states and inputs, ridge regression
// (methods/lti/lti.h), registered in methods/method_list.h. It is also the example of
// docs/adding-a-method.md, which it follows step by step.
#include "methods/channel_fit.h"
#include "methods/lti/lti.h"
#include "methods/method.h"

namespace usvid {
namespace {

nlohmann::json IdentifyLtiModel(const Dataset& data, const IdentifyRequest& request,
                                const MethodOptions& o, const Logger& log) {
  lti::LtiOptions options;
  options.ridge = o.Number("ridge");
  options.constant = o.Text("constant") == "yes";
  ChannelFit fit = PrepareChannelFit(data, request, DefaultChannels(request, data), log);
  const lti::LtiIdentification id = lti::IdentifyLti(
      fit.prepared, fit.channels.states, fit.channels.variables, fit.channels.inputs, options);
  fit.model["parameters"] = id.parameters;
  fit.model["equations"] = id.equations;
  fit.model["lti"] = id.details;
  SetTrain(fit, request);
  return fit.model;
}

}  // namespace

Method LtiMethod() {
  Method m;
  m.name = std::string(lti::kMethodName);
  m.summary = "each derivative linear in the states and inputs, ridge regression";
  const lti::LtiOptions d;  // the defaults are the estimator's own
  m.options = {
      NumberOption("ridge", d.ridge, 0, kUnbounded, "ridge, relative to each column's energy"),
      ChoiceOption("constant", d.constant ? "yes" : "no", {"yes", "no"},
                   "a constant term in each equation"),
  };
  m.identify = IdentifyLtiModel;
  m.channel_inputs = true;
  m.any_inputs = true;
  return m;
}

}  // namespace usvid
