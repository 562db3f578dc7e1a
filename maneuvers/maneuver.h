// A maneuver decides the commanded inputs over time, open-loop or closed-loop on the measured
// state. It is called once per control period, in time order, and its command is held until the
// next call. Maneuvers know a vessel only through its Actuation: which input steers, which
// drives, their ranges, and where heading, speed and rate sit in the state.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <vector>

namespace usvid {

enum class InputRole {
  kThrust,  // drives forward: held, stepped or varied by the maneuver
  kYaw,     // steers: the maneuver's main channel
  kSide,    // a free extra input (sway force): zero in classic maneuvers, excited in random ones
  kFixed,   // held at its neutral value (reversing bucket)
  // A measured disturbance, not a command (the relative wind): held at its neutral value (none)
  // in generated maneuvers, read from a record that has its channel, neutral in one that has
  // not; no actuator effect acts on it.
  kMeasured,
};

struct Actuation {
  std::vector<std::string> input_names;
  std::vector<InputRole> roles;
  std::vector<double> input_min, input_max;
  std::vector<double> neutral;  // the inputs at rest
  int yaw_input = -1;
  int thrust_input = -1;   // -1: the vessel has no thrust input (msd)
  int heading_state = -1;  // psi or chi; -1: no heading (msd)
  int rate_state = -1;
  int north_state = -1, east_state = -1;  // positions, -1: none
  int speed_state = -1;                   // U, or surge u (with sway v next) when speed_is_surge
  bool speed_is_surge = false;
  // Full yaw command: for an angle input (nozzle, rudder) the command of `yaw_full_deg`
  // degrees is that angle in radians; for a moment input, yaw_full_deg maps to yaw_full.
  bool yaw_is_angle = false;
  double yaw_full = 1.0;
  double yaw_full_deg = 35.0;
  double thrust_cruise = 0.0;  // the thrust command of the default cruise
  // +1 when a positive yaw input turns to starboard (r > 0), -1 when it turns to port (the ITTC
  // rudder sign of kvlcc2's MARIN data). Maneuvers think in starboard-positive degrees.
  double yaw_sign = 1.0;
  // Largest rate of change of the yaw command in classic maneuvers (zig-zag, turning) [input
  // units per second]; 0: the command steps (a servo fast against the hull's response).
  double yaw_rate_limit = 0.0;

  int inputs() const { return static_cast<int>(input_names.size()); }
  // The yaw command standing for a rudder angle of `deg` degrees to starboard, within the
  // input's range.
  double YawCommand(double deg) const;
  // The yaw command moved from `from` towards `to` within yaw_rate_limit over dt seconds.
  double SlewYaw(double from, double to, double dt) const;
  // Speed over ground from a state (U, or the norm of u and v); 0 without a speed state.
  double Speed(std::span<const double> state) const;
};

// Classic maneuvers (zig-zag, turning) start with this long a straight approach at cruise.
inline constexpr double kLeadInS = 5.0;

class Maneuver {
 public:
  virtual ~Maneuver() = default;
  virtual std::string Spec() const = 0;
  // Seconds the maneuver runs (after the run-in to steady state).
  virtual double Duration() const = 0;
  // The inputs the vessel is brought to steady state with before t = 0.
  virtual std::vector<double> InitialCommand() const = 0;
  // The command from t until the next call, given the measured state.
  virtual void Command(double t, std::span<const double> state, std::span<double> u) = 0;
  // Whether the maneuver has finished early (closed-loop grids end when done).
  virtual bool Done() const { return false; }
  // What the maneuver measured of the run, for F.truth.json (e.g. zig-zag overshoots).
  virtual nlohmann::json Report() const { return nlohmann::json::object(); }
  // A copy in the state this one is in: a closed-loop maneuver keeps state as it runs (a zig-zag
  // its base course and side, a grid its step), so a second run, such as a saturation's probe
  // of the peak command (simulation/typed_vessel_simulator.h), needs a fresh copy, not this one.
  virtual std::unique_ptr<Maneuver> Clone() const = 0;
};

// The maneuver a wrapper runs inside (a replay's approach, a wind over a maneuver): owned, and
// cloned with its wrapper, so that the wrapper's Clone is its copy.
class InnerManeuver {
 public:
  explicit InnerManeuver(std::unique_ptr<Maneuver> m) : m_(std::move(m)) {}
  InnerManeuver(const InnerManeuver& o) : m_(o.m_->Clone()) {}
  InnerManeuver& operator=(const InnerManeuver& o) {
    if (this != &o) m_ = o.m_->Clone();
    return *this;
  }
  InnerManeuver(InnerManeuver&&) noexcept = default;
  InnerManeuver& operator=(InnerManeuver&&) noexcept = default;
  ~InnerManeuver() = default;
  Maneuver* operator->() const { return m_.get(); }

 private:
  std::unique_ptr<Maneuver> m_;
};

}  // namespace usvid
