// Turning circle at A degrees (A > 0 to starboard): after a straight approach of kLeadInS at
// cruise, the yaw command goes to A degrees and is held; thrust stays at cruise. Report: advance
// and transfer [m] at 90 deg of heading change, tactical diameter [m] (transfer at 180 deg), and
// the steady turning radius U / |r| [m] over the last full turn, when the state has positions and
// speeds.
#pragma once

#include <memory>

#include "maneuvers/maneuver.h"
#include "maneuvers/slewed_yaw.h"

namespace usvid {

class Turning : public Maneuver {
 public:
  Turning(const Actuation& act, double rudder_deg, double duration_s);

  std::string Spec() const override;
  double Duration() const override { return duration_s_; }
  std::vector<double> InitialCommand() const override;
  void Command(double t, std::span<const double> state, std::span<double> u) override;
  nlohmann::json Report() const override;

  std::unique_ptr<Maneuver> Clone() const override { return std::make_unique<Turning>(*this); }

 private:
  Actuation act_;
  double rudder_deg_, duration_s_;
  bool started_ = false;
  double psi0_ = 0.0, north0_ = 0.0, east0_ = 0.0;
  double advance_ = -1.0, transfer_ = -1.0, tactical_ = -1.0;
  double last_radius_ = -1.0;
  SlewedYaw yaw_;
};

}  // namespace usvid
