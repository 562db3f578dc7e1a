// Eriksen-Breivik step grid: a grid of thrust x yaw commands (throttle x nozzle, or tau_x x
// tau_n for force-driven vessels), each step held until steady state is detected, then, when
// turning, held on for a full turn (360 deg of heading) to average out the environment.
// Thrust levels: `thrust_levels` evenly from 25 % to 100 % of the thrust range; yaw levels:
// 0 and +-k/yaw_levels of full yaw, k = 1..yaw_levels, alternating sides.
// Steady state: over the last `window_s` the speed and the rate each moved less than
// 0.5 % of the speed + 0.01 m/s and 0.001 rad/s; a step lasts at least min_hold_s and at most
// max_hold_s. With a fixed hold (`hold_s` > 0, spec stepgrid:T/Y/H) every step is held exactly
// that long instead, with no steady test and no turn: a schedule whose length is known before
// the run, T (1 + 2 Y) H seconds. The report lists every step with its steady window and steady
// speed and rate.
// Throws InputError for a vessel without thrust and speed, levels out of range, or a fixed hold
// shorter than kMinHoldS, too short for any steady window (StepGridHoldError names both).
#pragma once

#include <deque>
#include <memory>

#include "maneuvers/maneuver.h"

namespace usvid {

// The shortest fixed hold [s] a step may have: the vessel must settle after the step (at least
// kSettleS) and then stay steady for eb-lr's shortest steady window (kSteadyWindowS, its
// min_window_s), whatever the vessel; a slower one needs longer (docs/baselines.md).
inline constexpr double kSettleS = 5.0;
inline constexpr double kSteadyWindowS = 3.0;
inline constexpr double kMinHoldS = kSettleS + kSteadyWindowS;

struct StepGridOptions {
  int thrust_levels = 4;
  int yaw_levels = 3;
  double hold_s = 0.0;  // > 0: every step held this long (no steady test, no turn) [s]
  double window_s = 4.0;
  double min_hold_s = 8.0;
  double max_hold_s = 90.0;
  double max_turn_s = 60.0;
  bool full_turn = true;
};

class StepGrid : public Maneuver {
 public:
  StepGrid(const Actuation& act, const StepGridOptions& options, double max_duration_s);

  std::string Spec() const override;
  double Duration() const override { return max_duration_s_; }
  std::vector<double> InitialCommand() const override;
  void Command(double t, std::span<const double> state, std::span<double> u) override;
  bool Done() const override { return step_ >= grid_.size(); }
  nlohmann::json Report() const override;

  std::unique_ptr<Maneuver> Clone() const override { return std::make_unique<StepGrid>(*this); }

 private:
  struct Sample {
    double t, speed, rate;
  };
  struct Step {
    double thrust, yaw;
    double start = 0, steady = -1, end = -1, speed = 0, rate = 0;
  };
  bool Steady() const;

  Actuation act_;
  StepGridOptions opt_;
  double max_duration_s_;
  std::vector<Step> grid_;
  size_t step_ = 0;
  std::deque<Sample> window_;
  double turned_ = 0.0, last_heading_ = 0.0;
};

}  // namespace usvid
