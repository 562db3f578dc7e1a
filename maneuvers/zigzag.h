// Kempf zig-zag A/B (ITTC): after a straight approach of kLeadInS, the yaw command goes to +A
// degrees to starboard (zigzag:-A/B: to port first); when the heading has turned B degrees from
// the initial heading it reverses, when it has turned B the other way it reverses again, and so
// on, closed-loop on the measured heading (about a base course set off that initial heading, in a
// replay of a record whose test was: `base_offset_rad`). Thrust is held at cruise. For a
// moment-driven vessel the yaw command is the moment standing for A degrees
// (Actuation::YawCommand). Report: the first and second overshoot angles [deg] (how far the heading
// goes beyond B after the first and second switch), the switch times, and the heading rate at each
// switch.
#pragma once

#include <memory>

#include "maneuvers/maneuver.h"
#include "maneuvers/slewed_yaw.h"

namespace usvid {

class ZigZag : public Maneuver {
 public:
  // Throws InputError when the vessel has no heading. `base_offset_rad`: reverse about a base
  // course that far off the heading at the execute, as the record being replayed did
  // (metrics/zigzag_response.h), instead of about that heading.
  ZigZag(const Actuation& act, double rudder_deg, double heading_deg, double duration_s,
         double base_offset_rad = 0.0);

  std::string Spec() const override;
  double Duration() const override { return duration_s_; }
  std::vector<double> InitialCommand() const override;
  void Command(double t, std::span<const double> state, std::span<double> u) override;
  nlohmann::json Report() const override;

  std::unique_ptr<Maneuver> Clone() const override { return std::make_unique<ZigZag>(*this); }

 private:
  Actuation act_;
  double rudder_deg_, heading_deg_, duration_s_;
  double psi0_ = 0.0;   // the base course
  double base_offset_;  // the base course less the heading at the execute
  bool started_ = false;
  int sign_ = 1;        // current yaw command direction (+1 starboard)
  int first_sign_ = 1;  // the first turn's (zigzag:-A/B turns to port first)
  std::vector<double> switch_times_;
  // Largest excursion beyond the threshold after each switch [rad], sign-corrected.
  std::vector<double> overshoot_;
  SlewedYaw yaw_;
};

}  // namespace usvid
