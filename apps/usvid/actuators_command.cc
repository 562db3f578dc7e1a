// usvid actuators --data F.csv [--max-delay S] --out actuators.json
// The actuator dynamics of a waterjet log from command to measured state (throttle -> rpm,
// nozzle -> nozzle_angle, bucket -> bucket_position; preprocessing/actuator_dynamics.h): delay,
// gain, offset, time constant and slew rate of each pair the log records and moves. A pair whose
// command is held has nothing to identify and is left out with a note. The file drives
// `--actuators` of preprocess, identify and evaluate on logs that record the commands only.

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>

#include "apps/usvid/commands.h"
#include "apps/usvid/data_file.h"
#include "core/atomic_file.h"
#include "core/csv_dataset.h"
#include "core/error.h"
#include "preprocessing/actuator_dynamics.h"

namespace usvid {
namespace {

struct ActuatorsCommandOptions {
  std::string data;
  double max_delay_s = 1.0;
  std::string out;
};

bool Varies(const Dataset& data, const std::string& name) {
  const Eigen::VectorXd& x = data[name];
  double low = INFINITY, high = -INFINITY;
  for (double v : x)
    if (std::isfinite(v)) low = std::min(low, v), high = std::max(high, v);
  return high > low;
}

void RunActuators(const ActuatorsCommandOptions& o) {
  const Dataset data = ReadDataFile(o.data, "usvid actuators");
  ActuatorOptions options;
  options.max_delay_s = o.max_delay_s;
  std::vector<ActuatorModel> models;
  for (const auto& [command, state] : kWaterjetActuators) {
    if (!data.Has(command) || !data.Has(state)) {
      std::cerr << "usvid actuators: " << command << " -> " << state << ": not in " << o.data
                << '\n';
      continue;
    }
    if (!Varies(data, command)) {
      std::cerr << "usvid actuators: " << command << " -> " << state
                << ": the command is held; nothing to identify\n";
      continue;
    }
    models.push_back(IdentifyActuator(data, command, state, options));
    const ActuatorModel& m = models.back();
    std::cerr << "usvid actuators: " << command << " -> " << state << ": delay " << m.delay_s
              << " s, gain " << m.gain << ", offset " << m.offset << ", time constant "
              << m.time_constant_s << " s, rate "
              << (m.RateLimited() ? std::to_string(m.rate_max) + " /s" : "not shown") << '\n';
  }
  if (models.empty())
    throw InputError(o.data +
                     ": no actuator to identify: it needs a command and its state that "
                     "moves (throttle and rpm, nozzle and nozzle_angle, bucket and "
                     "bucket_position)");
  WriteFileAtomically(
      o.out,
      nlohmann::json{{"data", o.data}, {"actuators", ActuatorModelsToJson(models)}}.dump(2) + "\n");
  std::cerr << "usvid actuators: wrote " << o.out << '\n';
}

}  // namespace

void AddActuatorsCommand(CLI::App& app) {
  auto o = std::make_shared<ActuatorsCommandOptions>();
  CLI::App* cmd = app.add_subcommand(
      "actuators",
      "Identify the waterjets' actuator dynamics (delay, gain, lag, slew rate) from command to "
      "measured state");
  cmd->add_option("--data", o->data, "Data CSV with commands and actuator states")->required();
  cmd->add_option("--max-delay", o->max_delay_s, "Longest delay considered [s] (1)");
  cmd->add_option("--out", o->out, "actuators.json to write")->required();
  cmd->callback([o] { RunActuators(*o); });
}

}  // namespace usvid
