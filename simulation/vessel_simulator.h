// A vessel behind a runtime interface, so that the command line and the harness can pick one
// by name: its channel and parameter names, and runs of a maneuver or of recorded inputs with
// effects. The typed implementation is simulation/typed_vessel_simulator.h; the list of
// vessels is vessel_registry.cc (one line a vessel).
#pragma once

#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/dataset.h"
#include "effects/effect_values.h"
#include "maneuvers/maneuver.h"
#include "simulation/run_options.h"
#include "simulators/vessel.h"

namespace usvid {

struct VesselInfo {
  std::string name;
  // The compiled vessel type whose dynamics run it (simulators/vessel_types.h): the name itself
  // for the compiled-in vessels, "mmg" for a vessel file.
  std::string type;
  std::vector<std::string> states;   // the integrated states, in order
  std::vector<std::string> derived;  // channels computed from the states (U, chi)
  std::vector<std::string> inputs;
  std::vector<std::string> params;
  std::vector<double> default_params;
  std::vector<ParamGroup> groups;
  Actuation actuation;
  double transport_delay_s = 0.0;
  double length_m = 0.0;  // hull length where the model has one (Froude number, time scale L/U)
  // The model writes its hydrodynamic forces as 1/2 rho L d U^2 times coefficients of the
  // nondimensional v' = v/U, r' = r L/U and the inputs (MMG): what it lacks is of that form too
  // (the hybrid method's proposals, methods/hybrid/term_proposals.h).
  bool speed_scaled_forces = false;
  // A vessel file's coefficients that it did not give, each "name = value (source)": estimated
  // from its particulars (simulation/mmg_estimates.h). Empty for the compiled-in vessels.
  std::vector<std::string> estimated;
  // What a reader of the vessel file is told once: how many coefficients were estimated, and
  // the file's warnings. Empty for the compiled-in vessels.
  std::vector<std::string> notes;
  // The vessel feels the wind: it has a wind model (simulators/wind_force.h) with areas, driven
  // by its measured inputs wind_speed and wind_direction (a vessel file with a wind section).
  bool wind_body = false;

  // Whether input i is a measured disturbance (InputRole::kMeasured), not a command.
  bool IsMeasuredInput(size_t i) const;
  // The inputs that are commands, in order: what the equation methods take by default.
  std::vector<std::string> CommandedInputs() const;
  // The inputs `data` holds: every command, and the measured disturbances it logged.
  std::vector<std::string> InputsIn(const Dataset& data) const;
  int StateIndex(const std::string& name) const;  // -1 when absent
  // Parameters by name over the defaults; throws InputError on an unknown name.
  std::vector<double> ParamsFrom(const nlohmann::json& overrides) const;
  // ParamsFrom a JSON file of overrides, or of a truth/model file's "parameters"; errors name
  // the file.
  std::vector<double> ParamsFromFile(const std::string& path) const;
};

struct SimulationResult {
  Dataset data;             // t, states, derived channels, inputs (the commands)
  nlohmann::json maneuver;  // spec and what the maneuver measured
  double run_in_s = 0.0;
  bool diverged = false;
  double diverged_at_s = 0.0;
};

class VesselSimulator {
 public:
  virtual ~VesselSimulator() = default;
  virtual const VesselInfo& Info() const = 0;
  // Closed- or open-loop maneuver from steady state; saturation limits are taken from the
  // peak commands of a first run without saturation.
  virtual SimulationResult RunManeuver(Maneuver& maneuver, const std::vector<double>& params,
                                       const EffectValues<double>& effects,
                                       const RunOptions& options) const = 0;
  // Recorded inputs (the data's input channels, zero-order hold, unsampled cells hold the last
  // sample), output at the data's time stamps, initial state from its first row where present.
  virtual SimulationResult RunInputs(const Dataset& inputs, const std::vector<double>& params,
                                     const EffectValues<double>& effects,
                                     const RunOptions& options) const = 0;
  // Calm-water resistance [N] at a speed [m/s], for vessels whose model has one (odin-hs).
  virtual std::optional<double> Resistance(double speed,
                                           const std::vector<double>& params) const = 0;
  // Froude number U / sqrt(g L) for vessels with a length (odin-hs).
  virtual std::optional<double> FroudeNumber(double speed) const = 0;
};

// A compiled-in vessel by name, or a vessel file (simulation/vessel_file.h) by its path: a
// name ending in .yaml, .yml or .json. A file is read once and kept; its notes (VesselInfo::notes)
// go to the note sink then. Throws InputError listing the known vessels, or naming the file's
// fault.
const VesselSimulator& FindVessel(const std::string& name);
// Where a vessel file's notes go when it is first read, one call a line, never two at once: the
// command line and the Python module send them to stderr. Unset (a library's caller), they stay
// in VesselInfo::notes alone.
void SetVesselNoteSink(std::function<void(const std::string&)> sink);
// The compiled-in vessels.
std::vector<std::string> VesselNames();
// What --vessel takes, for help texts: "eb2dof, kvlcc2, ..., or a vessel file (...)".
std::string VesselChoices();
// Whether `name` names a vessel file (by its extension; the file may not exist).
bool IsVesselFile(const std::string& name);
// How a vessel is named to a reader (tables, headings, plot titles): a vessel file's `name:` (its
// stem when it has none, or when the file cannot be read), not the path it was read from; a
// compiled-in vessel's name as given.
std::string VesselLabel(const std::string& name);

}  // namespace usvid
