// What the methods that fit equations in channel names share (gp, sindy, eb-lr, fossen-ceres,
// nomoto): the channels (the request's, or a vessel's), the data preprocessed for them, and
// model.json's common fields. Vessel models (refit, hybrid, nominal) fit a simulator instead.
#pragma once

#include <chrono>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/dataset.h"
#include "methods/identify_request.h"
#include "methods/method.h"
#include "preprocessing/pipeline.h"
#include "simulation/vessel_ref.h"

namespace usvid {

struct Channels {
  std::vector<std::string> states;     // with an equation each
  std::vector<std::string> variables;  // the equations may use them (states and more)
  std::vector<std::string> inputs;
};

// A vessel's states less positions, heading and actuator feedback: what its dynamics depend on.
std::vector<std::string> VesselVariables(const VesselRef& vessel);

// The request's --states and --inputs, else the vessel's: its states less positions, heading
// and actuator feedback (and the msd's position x, which has no equation but is a variable),
// and its inputs, or the forces of the request's force map. Throws InputError when neither
// names them.
Channels DefaultChannels(const IdentifyRequest& request);

// The same; when neither the request nor a vessel names them, the record's own: the body
// velocities u, v, r it has (U for u when it has no u) as the states, and as the inputs the
// commands of the data contract it has (kRecordCommands,
// docs/data.md#channels-read-from-a-record).
// Throws InputError when the record has no state or no command among them.
Channels DefaultChannels(const IdentifyRequest& request, const Dataset& data);

// The commands a record's own channels are read as when nothing names the inputs.
inline const std::vector<std::string> kRecordCommands = {
    "delta", "n", "rev", "throttle", "nozzle", "bucket", "tau_x", "tau_y", "tau_n", "f"};

struct ChannelFit {
  Channels channels;
  PreparedData prepared;
  nlohmann::json model;  // method, vessel, states, variables, inputs, seed, preprocessing
  std::chrono::steady_clock::time_point start;
};

// The data preprocessed for the channels (a force map's forces are continuous: no step breaks).
ChannelFit PrepareChannelFit(const Dataset& data, const IdentifyRequest& request,
                             Channels channels, const Logger& log);

// model.json's train field: the data's name, the samples fitted, the seconds since start.
void SetTrain(ChannelFit& fit, const IdentifyRequest& request);

}  // namespace usvid
