// Training data recorded under a heading autopilot, as most logs at sea are: a PID on the
// measured heading tracks a course that the operator changes now and then, while the throttle is
// stepped. The yaw command then answers the vessel's own motion and every disturbance acting on
// it (a current, a missing moment), so input and disturbance are correlated: the
// closed-loop-identification problem that open-loop maneuvers avoid (docs/compare.md#realistic).
//   setpoint   psi_ref: the initial heading, then every hold_s (uniform in [hold/2, 3 hold/2])
//              a new course uniform within +-course_span_deg of the initial heading (default
//              kDefaultCourseSpanDeg)
//   yaw        delta = Kp e - Kd r + Ki integral(e) [deg of rudder, starboard positive], with
//              e = psi_ref - psi wrapped to +-180 deg and r in deg/s; clipped at +-yaw_full_deg
//              (the command saturates on every large course change) and slewed at the
//              vessel's yaw rate limit; the integral stops while the command is clipped
//   thrust     random levels within the excitation range, held 2-6 x hold_s
//   side       a side input (odin3dof's sway force), if any, at random levels within its range,
//              held hold_s / 6 to hold_s / 2, as random-steps does: the operator's own use of
//              a side thruster, which the autopilot does not close a loop on
// Gains are the same for every vessel, in rudder degrees: full rudder at 20 deg of heading
// error, derivative time 3 s, integral time 60 s. They are a plausible commercial tuning, not an
// optimal one for any vessel: a slow ship overshoots its course more, which only adds excitation.
// Report: the course changes (times [s] and courses [deg] from the initial heading, the first
// at t = 0), the RMS heading error [deg] and the share of control periods with the yaw command
// clipped.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "maneuvers/maneuver.h"
#include "maneuvers/slewed_yaw.h"
#include "maneuvers/steps.h"

namespace usvid {

class Autopilot : public Maneuver {
 public:
  static constexpr double kDefaultCourseSpanDeg = 60.0;
  static constexpr double kFullErrorDeg = 20.0;    // heading error that commands full rudder
  static constexpr double kDerivativeTimeS = 3.0;  // Kd = Kp x this
  static constexpr double kIntegralTimeS = 60.0;   // Ki = Kp / this

  // Throws InputError when the vessel has no heading or yaw rate, or hold_s or course_span_deg
  // is not positive.
  Autopilot(const Actuation& act, double hold_s, double duration_s, uint64_t seed,
            double course_span_deg = kDefaultCourseSpanDeg);

  std::string Spec() const override;
  double Duration() const override { return duration_s_; }
  std::vector<double> InitialCommand() const override;
  void Command(double t, std::span<const double> state, std::span<double> u) override;
  nlohmann::json Report() const override;

  std::unique_ptr<Maneuver> Clone() const override { return std::make_unique<Autopilot>(*this); }

 private:
  Actuation act_;
  double hold_s_, duration_s_, course_span_deg_;
  Steps course_;  // setpoint offsets from psi0 [rad]
  Steps thrust_, side_;
  int side_input_ = -1;
  bool started_ = false;
  double psi0_ = 0.0, integral_ = 0.0, last_t_ = 0.0;
  double error_sq_sum_ = 0.0;
  long periods_ = 0, clipped_ = 0;
  SlewedYaw yaw_;
};

}  // namespace usvid
