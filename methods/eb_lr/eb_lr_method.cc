// `eb-lr`: Eriksen-Breivik regression of the 2-DOF high-speed model (methods/eb_lr/eb_lr.h),
// registered in methods/method_list.h.
#include <algorithm>

#include "core/error.h"
#include "methods/channel_fit.h"
#include "methods/eb_lr/eb_lr.h"
#include "methods/method.h"
#include "simulation/vessel_simulator.h"

namespace usvid {
namespace {

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

// The Eriksen-Breivik 2-DOF form: speed U and rate r, driven by thrust and yaw inputs: the
// commands, or with the waterjet map the jets' surge force and yaw moment.
Channels EbLrChannels(const IdentifyRequest& o) {
  Channels c = DefaultChannels(o);
  if (!o.vessel.empty() && o.states.empty()) {
    const Actuation& a = FindVessel(o.vessel).Info().actuation;
    if (a.thrust_input < 0)
      throw InputError("--method eb-lr: vessel " + o.vessel + " has no thrust input");
    c.states = c.variables = {"U", "r"};
    if (o.inputs.empty())
      c.inputs = o.preprocess.forces == "waterjet"
                     ? std::vector<std::string>{"tau_x", "tau_n"}
                     : std::vector<std::string>{a.input_names[a.thrust_input],
                                                a.input_names[a.yaw_input]};
  }
  if (c.states.size() != 2 || c.inputs.size() != 2)
    throw InputError("--method eb-lr: needs --states SPEED,RATE and --inputs THRUST,YAW");
  return c;
}

nlohmann::json IdentifyEbLrModel(const Dataset& data, const IdentifyRequest& o,
                                 const MethodOptions&, const Logger& log) {
  ChannelFit fit = PrepareChannelFit(data, o, EbLrChannels(o), log);
  const std::vector<std::string>& states = fit.channels.states;
  const std::vector<std::string>& inputs = fit.channels.inputs;
  const eb_lr::EbLrOptions eo = EbLrOptionsFor(o, inputs, data);
  const eb_lr::EbLrIdentification id =
      eb_lr::IdentifyWithEbLr(data, states[0], states[1], inputs[0], inputs[1], eo);
  fit.model["parameters"] = id.parameters;
  fit.model["equations"] = id.equations;
  fit.model["eb_lr"] = id.details;
  if (!eo.thrust_loss_channel.empty() &&
      std::ranges::find(inputs, eo.thrust_loss_channel) == inputs.end())
    fit.model["inputs"].push_back(eo.thrust_loss_channel);
  SetTrain(fit, o);
  return fit.model;
}

}  // namespace

Method EbLrMethod() {
  Method m;
  m.name = std::string(eb_lr::kMethodName);
  m.summary = "Eriksen-Breivik 2-DOF regression on step-grid data";
  m.identify = IdentifyEbLrModel;
  m.channel_inputs = true;
  return m;
}

}  // namespace usvid
