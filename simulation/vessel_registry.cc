// The vessels usvid knows: one entry a vessel, with what maneuvers need to drive it.

#include <algorithm>
#include <functional>
#include <map>
#include <mutex>

#include "core/error.h"
#include "core/json_file.h"
#include "simulation/typed_vessel_simulator.h"
#include "simulation/vessel_file.h"
#include "simulators/eb2dof.h"
#include "simulators/kvlcc2.h"
#include "simulators/mmg.h"
#include "simulators/msd.h"
#include "simulators/odin3dof.h"
#include "simulators/odin_hs.h"

namespace usvid {
namespace {

constexpr double kNozzleMax = 27.0 * 3.14159265358979323846 / 180.0;
constexpr double kRudderMax = 35.0 * 3.14159265358979323846 / 180.0;

// What a maneuver needs beyond the vessel's own constants: how its yaw input maps to a rudder
// angle, and the thrust of a cruise.
Actuation Drive(bool yaw_is_angle, double yaw_full, double yaw_full_deg, double thrust_cruise,
                std::vector<double> neutral = {}) {
  Actuation a;
  a.yaw_is_angle = yaw_is_angle;
  a.yaw_full = yaw_full;
  a.yaw_full_deg = yaw_full_deg;
  a.thrust_cruise = thrust_cruise;
  a.neutral = std::move(neutral);
  return a;
}

template <Vessel V>
VesselInfo InfoFor(std::vector<InputRole> roles, const Actuation& extra) {
  VesselInfo info;
  info.name = std::string(V::kName);
  info.type = info.name;
  for (auto s : V::kStateNames) info.states.emplace_back(s);
  for (auto s : V::kInputNames) info.inputs.emplace_back(s);
  for (auto s : V::kParamNames) info.params.emplace_back(s);
  info.default_params.assign(V::kDefaultParams.begin(), V::kDefaultParams.end());
  info.groups.assign(V::kParamGroups.begin(), V::kParamGroups.end());
  if constexpr (requires { V::kDerivesSpeedAndCourse; }) info.derived = {"U", "chi"};
  if constexpr (requires { V::kTransportDelay; }) info.transport_delay_s = V::kTransportDelay;
  if constexpr (requires { V::kLength; }) info.length_m = V::kLength;
  if constexpr (requires { V::kSpeedScaledForces; }) info.speed_scaled_forces = true;

  Actuation& a = info.actuation;
  a = extra;
  a.input_names = info.inputs;
  a.roles = std::move(roles);
  if (a.input_min.empty()) {  // a vessel file gives its own
    a.input_min.assign(V::kInputMin.begin(), V::kInputMin.end());
    a.input_max.assign(V::kInputMax.begin(), V::kInputMax.end());
  }
  if (a.neutral.empty()) {
    if constexpr (requires { V::kNeutralInput; }) {
      a.neutral.assign(V::kNeutralInput.begin(), V::kNeutralInput.end());
    } else {
      a.neutral.assign(V::kInputs, 0.0);
    }
  }
  a.yaw_input = V::kYawInput;
  if constexpr (requires { V::kYawSign; }) a.yaw_sign = V::kYawSign;
  if constexpr (requires { V::kYawRateLimit; }) a.yaw_rate_limit = V::kYawRateLimit;
  a.thrust_input = V::kThrustInput;
  a.rate_state = V::kRateState;
  a.heading_state = V::kHeadingState;
  a.north_state = info.StateIndex("north");
  a.east_state = info.StateIndex("east");
  if (info.StateIndex("U") >= 0) {
    a.speed_state = info.StateIndex("U");
  } else if (info.StateIndex("u") >= 0 && info.StateIndex("v") == info.StateIndex("u") + 1) {
    a.speed_state = info.StateIndex("u");
    a.speed_is_surge = true;
  }
  return info;
}

template <Vessel V>
std::unique_ptr<VesselSimulator> Make(std::vector<InputRole> roles, const Actuation& extra) {
  return std::make_unique<TypedVesselSimulator<V>>(InfoFor<V>(std::move(roles), extra));
}

const std::map<std::string, std::unique_ptr<VesselSimulator>>& Registry() {
  static const auto* registry = [] {
    auto* r = new std::map<std::string, std::unique_ptr<VesselSimulator>>;
    using R = InputRole;
    // msd: the force is the channel every maneuver moves (+-10 N: x within about +-5 m).
    (*r)["msd"] = Make<Msd>({R::kYaw}, Drive(false, 10.0, 35.0, 0.0));
    // odin3dof: cruise tau_x = 16 kN (about 8 m/s); a yaw moment of 20 kN m stands for 35 deg.
    (*r)["odin3dof"] =
        Make<Odin3Dof>({R::kThrust, R::kSide, R::kYaw}, Drive(false, 20000.0, 35.0, 16000.0));
    // eb2dof: nozzle angle in radians, +-27 deg; cruise at half throttle.
    (*r)["eb2dof"] = Make<Eb2Dof>({R::kThrust, R::kYaw}, Drive(true, kNozzleMax, 27.0, 0.5));
    // odin-hs: throttle, nozzle [rad, +-27 deg], bucket held open (full ahead); cruise at
    // half throttle (5.4 m/s, semi-displacement).
    (*r)["odin-hs"] =
        Make<OdinHs>({R::kThrust, R::kYaw, R::kFixed}, Drive(true, kNozzleMax, 27.0, 0.5));
    // kvlcc2: rudder angle in radians, hard over 35 deg; cruise at the 91.7 rpm of the MARIN
    // free-running tests.
    (*r)["kvlcc2"] = Make<Kvlcc2>({R::kYaw, R::kThrust}, Drive(true, kRudderMax, 35.0, 91.7));
    return r;
  }();
  return *registry;
}

// A vessel file's vessel: the Mmg type with the file's parameters and controls.
std::unique_ptr<VesselSimulator> MakeFromFile(const std::string& path) {
  const VesselFile file = ReadVesselFile(path);
  VesselInfo info = InfoFor<Mmg>(
      {InputRole::kYaw, InputRole::kThrust, InputRole::kMeasured, InputRole::kMeasured},
      file.actuation);
  info.name = file.name;
  info.default_params = file.params;
  info.length_m = file.length_m;
  info.estimated = file.estimated;
  info.wind_body = file.wind_body;
  info.notes.push_back("usvid: vessel " + file.name + " (" + path +
                       "): " + std::to_string(file.estimated.size()) +
                       " coefficients not given, estimated from the particulars (usvid vessel "
                       "lists them; docs/model.md#vessel-files)");
  for (const std::string& w : file.warnings) info.notes.push_back("warning: " + path + ": " + w);
  return std::make_unique<TypedVesselSimulator<Mmg>>(std::move(info));
}

std::mutex& FilesMutex() {
  static std::mutex mutex;
  return mutex;
}

std::function<void(const std::string&)>& NoteSink() {
  static auto* sink = new std::function<void(const std::string&)>;
  return *sink;
}

const VesselSimulator& FileVessel(const std::string& path) {
  static auto* files = new std::map<std::string, std::unique_ptr<VesselSimulator>>;
  const std::lock_guard<std::mutex> lock(FilesMutex());
  auto it = files->find(path);
  if (it == files->end()) {
    it = files->emplace(path, MakeFromFile(path)).first;
    if (NoteSink())
      for (const std::string& note : it->second->Info().notes) NoteSink()(note);
  }
  return *it->second;
}

}  // namespace

void SetVesselNoteSink(std::function<void(const std::string&)> sink) {
  const std::lock_guard<std::mutex> lock(FilesMutex());
  NoteSink() = std::move(sink);
}

bool IsVesselFile(const std::string& name) {
  for (const char* ext : {".yaml", ".yml", ".json"})
    if (name.size() > std::string(ext).size() && name.ends_with(ext)) return true;
  return false;
}

std::string VesselLabel(const std::string& name) {
  if (!IsVesselFile(name)) return name;
  try {
    return FindVessel(name).Info().name;
  } catch (const InputError&) {  // a file gone since (a report re-read from results.json)
    return std::filesystem::path(name).stem().string();
  }
}

bool VesselInfo::IsMeasuredInput(size_t i) const {
  return i < actuation.roles.size() && actuation.roles[i] == InputRole::kMeasured;
}

std::vector<std::string> VesselInfo::CommandedInputs() const {
  std::vector<std::string> out;
  for (size_t i = 0; i < inputs.size(); ++i)
    if (!IsMeasuredInput(i)) out.push_back(inputs[i]);
  return out;
}

std::vector<std::string> VesselInfo::InputsIn(const Dataset& data) const {
  std::vector<std::string> out;
  for (size_t i = 0; i < inputs.size(); ++i)
    if (!IsMeasuredInput(i) || data.Has(inputs[i])) out.push_back(inputs[i]);
  return out;
}

int VesselInfo::StateIndex(const std::string& state) const {
  const auto it = std::find(states.begin(), states.end(), state);
  return it == states.end() ? -1 : static_cast<int>(it - states.begin());
}

std::vector<double> VesselInfo::ParamsFrom(const nlohmann::json& overrides) const {
  std::vector<double> p = default_params;
  if (overrides.is_null()) return p;
  if (!overrides.is_object()) throw InputError("parameters: expected an object of name: value");
  for (const auto& [key, value] : overrides.items()) {
    const auto it = std::find(params.begin(), params.end(), key);
    if (it == params.end())
      throw InputError("parameters: vessel " + name + " has no parameter '" + key + "'");
    if (!value.is_number()) throw InputError("parameters: '" + key + "' is not a number");
    p[it - params.begin()] = value.get<double>();
  }
  return p;
}

std::vector<double> VesselInfo::ParamsFromFile(const std::string& path) const {
  const nlohmann::json j = ReadJsonFile(path);
  try {
    return ParamsFrom(j.is_object() && j.contains("parameters") ? j.at("parameters") : j);
  } catch (const InputError& e) {
    throw InputError(path + ": " + e.what());
  }
}

const VesselSimulator& FindVessel(const std::string& name) {
  const auto& r = Registry();
  const auto it = r.find(name);
  if (it == r.end() && IsVesselFile(name)) return FileVessel(name);
  if (it == r.end()) {
    std::string known;
    for (const auto& [n, _] : r) known += (known.empty() ? "" : ", ") + n;
    throw InputError("--vessel '" + name + "': unknown vessel (known: " + known +
                     "; or a vessel file, .yaml or .json: docs/model.md#vessel-files)");
  }
  return *it->second;
}

std::vector<std::string> VesselNames() {
  std::vector<std::string> names;
  for (const auto& [n, _] : Registry()) names.push_back(n);
  return names;
}

std::string VesselChoices() {
  std::string names;
  for (const std::string& n : VesselNames()) names += n + ", ";
  return names + "or a vessel file (.yaml or .json: docs/model.md#vessel-files)";
}

}  // namespace usvid
