// `nomoto`: the first-order Nomoto heading model (methods/nomoto/nomoto.h), registered in
// methods/method_list.h.
#include "core/error.h"
#include "methods/channel_fit.h"
#include "methods/method.h"
#include "methods/nomoto/nomoto.h"
#include "simulation/vessel_simulator.h"

namespace usvid {
namespace {

// The rate of turn from the yaw input: a vessel's, or the one state and input named.
Channels NomotoChannels(const IdentifyRequest& o) {
  Channels c = DefaultChannels(o);
  if (!o.vessel.empty() && o.states.empty()) {
    const VesselInfo& info = o.vessel.Info();
    c.states = c.variables = {info.states[info.actuation.rate_state]};
    c.inputs = {info.actuation.input_names[info.actuation.yaw_input]};
  }
  if (c.states.size() != 1 || c.inputs.size() != 1)
    throw InputError("--method nomoto: needs --states RATE and --inputs YAW (one each)");
  return c;
}

nlohmann::json IdentifyNomotoModel(const Dataset& data, const IdentifyRequest& o,
                                   const MethodOptions& options, const Logger& log) {
  ChannelFit fit = PrepareChannelFit(data, o, NomotoChannels(o), log);
  const std::string& state = fit.channels.states[0];
  const std::string& input = fit.channels.inputs[0];
  const nomoto::NomotoFit n =
      nomoto::FitNomoto(fit.prepared, state, input, options.Number("segment_s"));
  fit.model["parameters"] = {{"K", n.K}, {"T", n.T}, {"delta0", n.delta0}};
  fit.model["equations"] = nomoto::NomotoEquations(n, state, input);
  fit.model["nomoto"] = {
      {"parameter_sd", {{"K", n.sd_K}, {"T", n.sd_T}, {"delta0", n.sd_delta0}}},
      {"equation_error",
       {{"K", n.equation_error_K}, {"T", n.equation_error_T}, {"delta0", n.equation_error_delta0}}},
      {"converged", n.converged},
      {"termination", n.termination},
      {"notes", n.notes}};
  for (const std::string& note : n.notes) Log(log, note);
  SetTrain(fit, o);
  return fit.model;
}

}  // namespace

Method NomotoMethod() {
  Method m;
  m.name = std::string(nomoto::kMethodName);
  m.summary = "first-order Nomoto heading model, T r' + r = K (delta - delta0)";
  m.options = {NumberOption("segment_s", 30.0, 0, kUnbounded, "shooting segment length [s]",
                            /*min_exclusive=*/true)};
  m.identify = IdentifyNomotoModel;
  return m;
}

}  // namespace usvid
