#include "maneuvers/step_grid.h"

#include <cmath>
#include <numbers>

#include "core/error.h"
#include "core/parse_number.h"
#include "maneuvers/excitation.h"

namespace usvid {

StepGrid::StepGrid(const Actuation& act, const StepGridOptions& options, double max_duration_s)
    : act_(act), opt_(options), max_duration_s_(max_duration_s) {
  if (act.thrust_input < 0 || act.speed_state < 0)
    throw InputError("--maneuver stepgrid: the vessel has no thrust input and speed");
  if (opt_.thrust_levels < 1 || opt_.yaw_levels < 0)
    throw InputError("--maneuver stepgrid:T/Y: T >= 1 thrust levels, Y >= 0 yaw levels a side");
  if (opt_.hold_s != 0.0 && !(opt_.hold_s >= kMinHoldS && std::isfinite(opt_.hold_s)))
    throw InputError("--maneuver " + Spec() + ": a hold of " + FormatNumber(opt_.hold_s) +
                     " s is too short for any steady window: each step needs at least " +
                     FormatNumber(kMinHoldS) + " s, " + FormatNumber(kSettleS) +
                     " s to settle and " + FormatNumber(kSteadyWindowS) +
                     " s of steady state for eb-lr's window (a slow vessel needs longer)");
  const double hi = ExcitationRange(act, act.thrust_input).second;
  const double base = std::max(act.input_min[act.thrust_input], 0.0);
  for (int i = 0; i < opt_.thrust_levels; ++i) {
    const double frac = opt_.thrust_levels == 1 ? 1.0 : 0.25 + 0.75 * i / (opt_.thrust_levels - 1);
    const double thrust = base + frac * (hi - base);
    grid_.push_back({thrust, 0.0});
    for (int k = 1; k <= opt_.yaw_levels; ++k) {
      const double yaw = act.yaw_full * k / opt_.yaw_levels;
      grid_.push_back({thrust, yaw});
      grid_.push_back({thrust, -yaw});
    }
  }
}

std::string StepGrid::Spec() const {
  return "stepgrid:" + std::to_string(opt_.thrust_levels) + "/" + std::to_string(opt_.yaw_levels) +
         (opt_.hold_s != 0.0 ? "/" + FormatNumber(opt_.hold_s) : "");
}

std::vector<double> StepGrid::InitialCommand() const {
  std::vector<double> u = CruiseCommand(act_);
  u[act_.thrust_input] = grid_.front().thrust;
  return u;
}

bool StepGrid::Steady() const {
  if (window_.size() < 2 || window_.back().t - window_.front().t < opt_.window_s * 0.999)
    return false;
  double s_min = INFINITY, s_max = -INFINITY, r_min = INFINITY, r_max = -INFINITY;
  for (const Sample& s : window_) {
    s_min = std::min(s_min, s.speed);
    s_max = std::max(s_max, s.speed);
    r_min = std::min(r_min, s.rate);
    r_max = std::max(r_max, s.rate);
  }
  return s_max - s_min < 0.005 * std::abs(s_max) + 0.01 && r_max - r_min < 0.001;
}

void StepGrid::Command(double t, std::span<const double> state, std::span<double> u) {
  std::vector<double> cmd = CruiseCommand(act_);
  if (step_ >= grid_.size()) {
    std::copy(cmd.begin(), cmd.end(), u.begin());
    return;
  }
  const double speed = act_.Speed(state);
  const double rate = state[act_.rate_state];
  const double heading = act_.heading_state >= 0 ? state[act_.heading_state] : 0.0;
  window_.push_back({t, speed, rate});
  while (window_.size() > 2 && window_.front().t < t - opt_.window_s) window_.pop_front();

  Step& s = grid_[step_];
  const double held = t - s.start;
  const bool fixed = opt_.hold_s > 0.0;
  bool next = fixed ? held >= opt_.hold_s - 1e-9 : held >= opt_.max_hold_s;
  if (!fixed && s.steady < 0 && held >= opt_.min_hold_s && Steady()) {
    s.steady = t;
    s.speed = speed;
    s.rate = rate;
    turned_ = 0.0;
    last_heading_ = heading;
  }
  if (s.steady >= 0) {
    turned_ += std::abs(heading - last_heading_);
    last_heading_ = heading;
    const bool turning = opt_.full_turn && std::abs(s.rate) > 1e-3 && act_.heading_state >= 0;
    next = next || !turning || turned_ >= 2 * std::numbers::pi || t - s.steady >= opt_.max_turn_s;
  }
  if (next) {
    s.end = t;
    ++step_;
    window_.clear();
    if (step_ < grid_.size()) grid_[step_].start = t;
  }
  const Step& now = grid_[std::min(step_, grid_.size() - 1)];
  if (step_ < grid_.size()) {
    cmd[act_.thrust_input] = now.thrust;
    cmd[act_.yaw_input] = now.yaw;
  }
  std::copy(cmd.begin(), cmd.end(), u.begin());
}

nlohmann::json StepGrid::Report() const {
  nlohmann::json steps = nlohmann::json::array();
  for (const Step& s : grid_) {
    nlohmann::json j = {{"thrust", s.thrust}, {"yaw", s.yaw}, {"start_s", s.start}};
    if (s.end >= 0) j["end_s"] = s.end;
    if (s.steady >= 0) {
      j["steady_from_s"] = s.steady;
      j["steady_speed"] = s.speed;
      j["steady_rate"] = s.rate;
    }
    steps.push_back(j);
  }
  return {{"steps", steps}, {"completed_steps", step_}};
}

}  // namespace usvid
