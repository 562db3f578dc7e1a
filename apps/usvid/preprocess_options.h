// The preprocessing flags shared by `usvid preprocess` and `usvid identify`:
// --rate, --interpolation, --derivative, --delay, --max-delay, --no-step-breaks, --forces.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "core/dataset.h"
#include "core/error.h"
#include "core/json_file.h"
#include "core/parse_number.h"
#include "preprocessing/actuator_dynamics.h"
#include "preprocessing/pipeline.h"

namespace usvid {

// --actuators FILE (from `usvid actuators`): each actuator state that `data` lacks is simulated
// from its command, so that a log of the commands alone can be turned into the jets' forces.
// States the log records are kept as measured. Throws InputError naming the file or channel.
inline void SimulateMissingActuators(Dataset& data, const std::string& file) {
  if (file.empty()) return;
  const nlohmann::json j = ReadJsonFile(file);
  if (!j.is_object() || !j.contains("actuators"))
    throw InputError(file + ": expected an object with \"actuators\" (from usvid actuators)");
  std::vector<ActuatorModel> missing;
  for (const ActuatorModel& m : ActuatorModelsFromJson(j["actuators"], file))
    if (!data.Has(m.state)) missing.push_back(m);
  SimulateActuators(data, missing);
}

struct PreprocessFlags {
  double rate_hz = 0.0;
  std::string interpolation = "spline";
  std::string derivative = "spline";
  std::string delay = "0";
  double max_delay_s = 2.0;
  bool no_step_breaks = false;
  // "waterjet": jet forces from the jet states (preprocessing/waterjet_forces.h)
  std::string forces;
  std::string actuators;  // actuators.json: jet states the log lacks, simulated from the commands

  // `fit_keys`: also --rate, --derivative and --forces; `usvid identify` makes those three from
  // the keys every method shares (harness/fit_service.h), as a suite reads them.
  void Add(CLI::App& cmd, bool fit_keys = true) {
    if (fit_keys)
      cmd.add_option("--rate", rate_hz, "Resample to this rate [Hz] (0: the data's own)");
    cmd.add_option("--interpolation", interpolation, "linear or spline")
        ->check(CLI::IsMember({"linear", "spline"}));
    if (fit_keys)
      cmd.add_option("--derivative", derivative,
                     "sg[:W[:P]], spline[:LAMBDA], tv[:ALPHA] or euler[:W] (the report's)");
    cmd.add_option("--delay", delay, "Input delay: auto (estimated) or seconds");
    cmd.add_option("--max-delay", max_delay_s, "Longest delay --delay auto considers [s]");
    cmd.add_flag("--no-step-breaks", no_step_breaks,
                 "Do not let derivatives jump where the inputs step");
    if (fit_keys)
      cmd.add_option("--forces", forces,
                     "waterjet: add the jets' forces tau_x, tau_y, tau_n from the measured rpm, "
                     "nozzle_angle and bucket_position, for --inputs to name")
          ->check(CLI::IsMember({"waterjet"}));
    cmd.add_option("--actuators", actuators,
                   "actuators.json from usvid actuators: the actuator states the log lacks are "
                   "simulated from its commands (a log of commands alone, with --forces)");
  }

  PreprocessOptions Options() const {
    PreprocessOptions o;
    o.rate_hz = rate_hz;
    o.interpolation =
        interpolation == "linear" ? Interpolation::kLinear : Interpolation::kCubicSpline;
    o.derivative = DerivativeMethod::Parse(derivative);
    o.step_breaks = !no_step_breaks;
    o.max_delay_s = max_delay_s;
    o.forces = forces;
    if (delay == "auto") {
      o.estimate_delay = true;
    } else {
      const ParsedNumber p = ParseNumber(delay);
      if (p.status != NumberStatus::kOk || p.value < 0)
        throw InputError("--delay '" + delay + "': expected auto or a non-negative number of s");
      o.delay_s = p.value;
    }
    return o;
  }
};

}  // namespace usvid
