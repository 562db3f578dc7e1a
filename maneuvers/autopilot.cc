#include "maneuvers/autopilot.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "core/error.h"
#include "maneuvers/excitation.h"

namespace usvid {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// An angle wrapped to [-pi, pi).
double Wrap(double a) {
  constexpr double kTurn = 2 * std::numbers::pi;
  return a - kTurn * std::floor((a + std::numbers::pi) / kTurn);
}

}  // namespace

Autopilot::Autopilot(const Actuation& act, double hold_s, double duration_s, uint64_t seed,
                     double course_span_deg)
    : act_(act), hold_s_(hold_s), duration_s_(duration_s), course_span_deg_(course_span_deg) {
  if (act.heading_state < 0 || act.rate_state < 0)
    throw InputError("--maneuver autopilot: the vessel has no heading and yaw rate");
  if (!(hold_s > 0 && std::isfinite(hold_s)))
    throw InputError("--maneuver autopilot:HOLD: HOLD must be positive seconds");
  if (!(course_span_deg > 0 && course_span_deg <= 180))
    throw InputError("--maneuver autopilot:HOLD/SPAN: SPAN must be in (0, 180] deg");
  std::seed_seq seq{static_cast<uint32_t>(seed), static_cast<uint32_t>(seed >> 32), 0xA070u};
  std::mt19937_64 rng(seq);
  std::uniform_real_distribution<double> span(0.5 * hold_s, 1.5 * hold_s);
  std::uniform_real_distribution<double> course(-course_span_deg * kDeg, course_span_deg * kDeg);
  course_ = {{0.0}, {0.0}};  // the initial heading first
  for (double t = span(rng); t < duration_s; t += span(rng)) {
    course_.times.push_back(t);
    course_.levels.push_back(course(rng));
  }
  if (act.thrust_input >= 0) {
    const auto [lo, hi] = ExcitationRange(act, act.thrust_input);
    thrust_ = Steps::Random(lo, hi, 2 * hold_s, 6 * hold_s, duration_s, rng);
  }
  for (int i = 0; i < act.inputs(); ++i)
    if (act.roles[i] == InputRole::kSide) side_input_ = i;
  if (side_input_ >= 0) {
    const auto [lo, hi] = ExcitationRange(act, side_input_);
    side_ = Steps::Random(lo, hi, hold_s / 6, hold_s / 2, duration_s, rng);
  }
}

std::string Autopilot::Spec() const {
  auto text = [](double x) {
    const double rounded = std::round(x);
    return rounded == x ? std::to_string(static_cast<int>(rounded)) : std::to_string(x);
  };
  return "autopilot:" + text(hold_s_) +
         (course_span_deg_ == kDefaultCourseSpanDeg ? "" : "/" + text(course_span_deg_));
}

std::vector<double> Autopilot::InitialCommand() const {
  std::vector<double> u = CruiseCommand(act_);
  if (act_.thrust_input >= 0) u[act_.thrust_input] = thrust_.levels.front();
  if (side_input_ >= 0) u[side_input_] = side_.levels.front();
  return u;
}

void Autopilot::Command(double t, std::span<const double> state, std::span<double> u) {
  const std::vector<double> cruise = CruiseCommand(act_);
  std::copy(cruise.begin(), cruise.end(), u.begin());
  if (act_.thrust_input >= 0) u[act_.thrust_input] = thrust_.At(t);
  if (side_input_ >= 0) u[side_input_] = side_.At(t);
  const double psi = state[act_.heading_state];
  if (!started_) {
    psi0_ = psi;
    last_t_ = t;
    started_ = true;
  }
  const double error_deg = Wrap(psi0_ + course_.At(t) - psi) / kDeg;
  const double rate_deg = state[act_.rate_state] / kDeg;
  const double kp = act_.yaw_full_deg / kFullErrorDeg;
  const double ki = kp / kIntegralTimeS, kd = kp * kDerivativeTimeS;
  const double unclipped = kp * error_deg - kd * rate_deg + ki * integral_;
  const double full = act_.yaw_full_deg;
  const bool clipped = std::abs(unclipped) > full;
  // Conditional integration: the integral holds while the command is clipped (no wind-up).
  if (!clipped) integral_ += error_deg * (t - last_t_);
  last_t_ = t;
  error_sq_sum_ += error_deg * error_deg;
  ++periods_;
  clipped_ += clipped ? 1 : 0;
  u[act_.yaw_input] = yaw_.Toward(act_, t, act_.YawCommand(std::clamp(unclipped, -full, full)));
}

nlohmann::json Autopilot::Report() const {
  const double n = std::max<double>(1.0, static_cast<double>(periods_));
  std::vector<double> courses_deg;
  for (double c : course_.levels) courses_deg.push_back(c / kDeg);
  return {{"hold_s", hold_s_},
          {"course_span_deg", course_span_deg_},
          {"course_times_s", course_.times},
          {"courses_deg", courses_deg},
          {"course_changes", course_.times.size() - 1},
          {"rms_heading_error_deg", std::sqrt(error_sq_sum_ / n)},
          {"clipped_share", static_cast<double>(clipped_) / n}};
}

}  // namespace usvid
