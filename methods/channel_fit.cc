#include "methods/channel_fit.h"

#include <set>

#include "core/error.h"
#include "preprocessing/waterjet_forces.h"
#include "simulation/vessel_simulator.h"

namespace usvid {
namespace {

// Positions and heading follow from the kinematics and need no equation; the dynamics do not
// depend on them either, except the msd's spring on x. Actuator feedback is left out.
const std::set<std::string> kNotVariables = {"north",        "east",           "psi", "chi", "rpm",
                                             "nozzle_angle", "bucket_position"};

std::vector<std::string> StatesExcept(const VesselInfo& info,
                                      const std::set<std::string>& excluded) {
  std::vector<std::string> out;
  for (const std::string& s : info.states)
    if (!excluded.contains(s)) out.push_back(s);
  return out;
}

}  // namespace

std::vector<std::string> VesselVariables(const VesselRef& vessel) {
  return StatesExcept(vessel.Info(), kNotVariables);
}

Channels DefaultChannels(const IdentifyRequest& o) {
  Channels c{o.states, o.states, o.inputs};
  if (!o.vessel.empty()) {
    const VesselInfo& info = o.vessel.Info();
    if (c.states.empty()) {
      c.variables = StatesExcept(info, kNotVariables);
      std::set<std::string> no_equation = kNotVariables;
      no_equation.insert("x");
      c.states = StatesExcept(info, no_equation);
    }
    // With a force map, the forces it derives stand in for the commands.
    if (c.inputs.empty())
      c.inputs =
          o.preprocess.forces.empty() ? info.CommandedInputs() : ForceChannels(o.preprocess.forces);
  }
  if (c.states.empty() || c.inputs.empty())
    throw InputError("identify: give --vessel, or --states and --inputs");
  return c;
}

Channels DefaultChannels(const IdentifyRequest& o, const Dataset& data) {
  if (!o.vessel.empty() || (!o.states.empty() && !o.inputs.empty())) return DefaultChannels(o);
  Channels c{o.states, o.states, o.inputs};
  if (c.states.empty()) {
    for (const char* state : {"u", "v", "r"})
      if (data.Has(state)) c.states.push_back(state);
    if (!data.Has("u") && data.Has("U")) c.states.insert(c.states.begin(), "U");
    c.variables = c.states;
  }
  if (c.inputs.empty())
    for (const std::string& command : kRecordCommands)
      if (data.Has(command)) c.inputs.push_back(command);
  if (c.states.empty() || c.inputs.empty()) {
    std::string commands;
    for (const std::string& command : kRecordCommands)
      commands += (commands.empty() ? "" : ", ") + command;
    throw InputError(
        data.SourcePrefix() + "identify: give --vessel, or --states and --inputs (the record has " +
        (c.states.empty() ? "none of the states u, v, r, U" : "no command among " + commands) +
        " to take by default)");
  }
  return c;
}

ChannelFit PrepareChannelFit(const Dataset& data, const IdentifyRequest& o, Channels channels,
                             const Logger& log) {
  ChannelFit fit;
  fit.start = std::chrono::steady_clock::now();
  PreprocessOptions pre = o.preprocess;
  // Forces from the actuators' states are continuous (slew-limited actuators): no input steps to
  // break the derivative spline at; every slewing sample would count as one.
  if (!pre.forces.empty()) pre.step_breaks = false;
  fit.prepared = Preprocess(data, channels.variables, channels.inputs, pre);
  for (const std::string& note : fit.prepared.notes) Log(log, note);
  fit.model = {
      {"method", o.method},
      {"vessel", o.vessel.Name()},
      {"states", channels.states},
      {"variables", channels.variables},
      {"inputs", channels.inputs},
      {"seed", o.seed},
      {"preprocessing",
       {{"delay_s", fit.prepared.delay_s},
        {"derivative", pre.derivative.Spec()},
        {"forces", pre.forces.empty() ? nlohmann::json(nullptr) : nlohmann::json(pre.forces)},
        {"step_breaks", pre.step_breaks},
        {"notes", fit.prepared.notes}}}};
  fit.channels = std::move(channels);
  return fit;
}

void SetTrain(ChannelFit& fit, const IdentifyRequest& o) {
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - fit.start).count();
  fit.model["train"] = {
      {"data", o.data_name}, {"samples", fit.prepared.data.rows()}, {"seconds", seconds}};
}

}  // namespace usvid
