// Actuator dynamics from data: how a measured actuator state (shaft speed, nozzle angle, bucket
// position) follows its command. The model is odin-hs's (simulators/odin_hs.h, section
// Actuators of docs/vessels/odin-hs.md), with a transport delay d in front:
//   y_cmd(t) = offset + gain u(t - d),   y' = rate_max tanh((y_cmd - y) / (tau rate_max)).
// Near the set point y follows y_cmd as a first-order lag of time constant tau; far from it, it
// slews at rate_max. Without a rate limit (rate_max = infinity) y' = (y_cmd - y) / tau.
// The command is held between its samples (zero-order hold, as a controller issues it).
// Exact steps: with a = (y_cmd - y) / (tau rate_max) and y_cmd held, sinh(a) decays as
// exp(-t / tau), so the simulation takes one exact step from sample to sample (and to each
// delayed command switch) and is continuous in the delay.
// Method: simulation (output) error. The state is simulated from the measured command, starting
// at the first measured state, and compared with the measured state at every sample.
//  1. Initial guesses from the data: gain and offset by least squares of the state on the command
//     at the ends of the stretches where the command holds; rate_max from the steepest slope of
//     the state over half a second; tau from a doubling grid, by simulation.
//  2. Ceres (autodiff through the exact steps) fits gain, offset, tau and 1 / rate_max^2 (0
//     without a limit, where the cost is smooth in it: it is even in 1 / rate_max) at each delay of
//     a grid (every sample period up to max_delay_s, at most 21 delays): the profile of the cost
//     over the delay. It follows the valley where a longer delay trades for a shorter tau, which
//     slowly varying commands leave shallow.
//  3. NLopt (Sbplx) refines the best delay of the grid to a fiftieth of a sample on the cost of
//     the same fit, which is continuous in the delay.
//  4. Standard deviations from the Jacobian at the solution, scaled by the residual variance.
// The rate limit is reported only when the record shows it: 1 / rate_max^2 at least
// rate_significance standard deviations above 0, and the largest |y_cmd - y| of the simulation
// at least min_saturation times tau rate_max (the tanh past its linear part). Otherwise the
// record cannot tell the rate limit from a first-order lag: rate_max is +infinity and the model
// is refitted without it.
#pragma once

#include <array>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "core/dataset.h"

namespace usvid {

struct ActuatorModel {
  std::string command;           // command channel, e.g. "throttle"
  std::string state;             // measured actuator state channel, e.g. "rpm"
  double delay_s = 0.0;          // [s] transport delay from command to actuator
  double gain = 1.0;             // [state units per command unit]
  double offset = 0.0;           // [state units] set point at command 0
  double time_constant_s = 0.0;  // [s] first-order time constant near the set point
  double rate_max = INFINITY;    // [state units/s] slew limit; +infinity: none shown
  double rms_error = NAN;        // [state units] standard deviation of the fit residual
  int samples = 0;               // state samples the fit compared
  // Standard deviations of the estimates from the noise alone (NaN when unknown; rate_max_sd
  // NaN without a slew limit).
  double delay_sd_s = NAN, gain_sd = NAN, offset_sd = NAN, time_constant_sd_s = NAN,
         rate_max_sd = NAN;

  // Whether the record showed a slew limit (rate_max finite).
  bool RateLimited() const { return std::isfinite(rate_max); }
};

struct ActuatorOptions {
  double max_delay_s = 1.0;        // delays searched in [0, max_delay_s]
  double rate_significance = 4.0;  // 1 / rate_max^2 over its standard deviation, at least
  double min_saturation = 1.0;     // largest |y_cmd - y| / (tau rate_max) in the record, at least
};

// The waterjet's command -> state pairs (odin-hs): throttle -> rpm, nozzle -> nozzle_angle,
// bucket -> bucket_position.
inline const std::array<std::pair<std::string, std::string>, 3> kWaterjetActuators = {
    {{"throttle", "rpm"}, {"nozzle", "nozzle_angle"}, {"bucket", "bucket_position"}}};

// Fits the model of the state channel driven by the command channel. Throws InputError naming
// the channel when one is missing, has a non-finite sample or is constant, when the record is
// too short (fewer than 20 state samples, or shorter than 4 max_delay_s), or for a negative
// max_delay_s.
ActuatorModel IdentifyActuator(const Dataset& data, const std::string& command,
                               const std::string& state, const ActuatorOptions& options = {});

// The three waterjet actuators (kWaterjetActuators), in that order. Throws as IdentifyActuator:
// a record whose bucket is held (as in odin-hs's stock maneuvers) cannot give the bucket's.
std::vector<ActuatorModel> IdentifyWaterjetActuators(const Dataset& data,
                                                     const ActuatorOptions& options = {});

// Adds each model's state channel simulated from its command channel (for logs that record the
// commands only), from the steady state of the first command, y = offset + gain u(0). Throws
// InputError naming a missing command channel, one with a non-finite sample, a state channel
// that the data (or an earlier model) already have, or a model without finite gain and offset,
// delay_s >= 0, time_constant_s > 0 and rate_max > 0; the data are unchanged then.
void SimulateActuators(Dataset& data, const std::vector<ActuatorModel>& models);

// The actuator state `h` seconds after `y`, with the (already delayed) command held: one exact
// step of the model (no delay applied here). For a closed loop that issues commands as it goes.
double ActuatorStep(const ActuatorModel& model, double y, double command, double h);

// A JSON array of the models: rate_max is null when not rate-limited, unknown deviations null.
nlohmann::json ActuatorModelsToJson(const std::vector<ActuatorModel>& models);
// The models of ActuatorModelsToJson (rms_error, samples and sd optional). Throws InputError
// naming the file and the field at fault.
std::vector<ActuatorModel> ActuatorModelsFromJson(const nlohmann::json& json,
                                                  const std::string& file);

}  // namespace usvid
