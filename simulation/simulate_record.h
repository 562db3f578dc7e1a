// One simulated record, as `usvid simulate`, a suite's simulated records and Python's simulate
// make it: a maneuver (or recorded inputs) run on a vessel with effects hidden in the plant, a
// mean wind and gusts, then the disturbances the record logs and what its sensors add (waves,
// noise, rates, dropouts; sensors/sensor_chain.h). Callers parse their flags, a suite's
// conditions or keywords into the recipe; the simulation is the same for all three.
#pragma once

#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/dataset.h"
#include "effects/effect.h"
#include "maneuvers/true_wind.h"
#include "sensors/sensor_chain.h"
#include "simulation/run_options.h"
#include "simulation/vessel_ref.h"

namespace usvid {

struct RecordRecipe {
  VesselRef vessel;                   // a registered vessel or a vessel file
  std::string maneuver;               // a maneuver spec; empty: `inputs` drive the run
  const Dataset* inputs = nullptr;    // recorded inputs (zero-order hold), when no maneuver
  double duration_s = 0.0;            // 0: the maneuver's own
  std::optional<double> cruise;       // the thrust input's cruise value; unset: the vessel's
  std::vector<double> params;         // empty: the vessel's defaults
  std::vector<Effect> effects;        // hidden in the plant
  RunOptions run;                     // grid and integrator; the rate rises to the fastest sensor
  std::optional<TrueWind> wind;       // a maneuver's mean true wind (maneuvers/true_wind.h)
  std::string gusts;                  // SPEED[:FROM_DEG] (simulation/wind_gusts.h); "": none
  std::string gusts_where = "gusts";  // how an error in `gusts` is introduced
  std::vector<std::string> logged;    // disturbances logged as channels (wind, current)
  SensorSpec sensors;                 // waves, noise, rates, dropouts
  uint64_t seed = 1;
};

struct SimulatedRecord {
  Dataset data;          // what the sensors logged
  nlohmann::json truth;  // the run's ground truth, as `usvid simulate` writes F.truth.json
  bool diverged = false;
  double diverged_at_s = 0.0;
};

// The recipe run. `log` (may be empty) hears one line naming the run before it starts.
// InputError for a bad maneuver, gust, sensor or rate item, naming it.
SimulatedRecord SimulateRecord(const RecordRecipe& recipe,
                               const std::function<void(const std::string&)>& log = {});

}  // namespace usvid
