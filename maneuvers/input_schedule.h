// An open-loop maneuver: the command is a function of time only, fixed before the run from
// the seed. Random steps, PRBS and multisine are schedules that differ in how they fill it.
#pragma once

#include <memory>

#include <functional>

#include "maneuvers/maneuver.h"

namespace usvid {

class InputSchedule : public Maneuver {
 public:
  // command(t, u) writes the inputs at time t.
  InputSchedule(std::string spec, double duration_s, int inputs,
                std::function<void(double, std::span<double>)> command)
      : spec_(std::move(spec)),
        duration_s_(duration_s),
        inputs_(inputs),
        command_(std::move(command)) {}

  std::string Spec() const override { return spec_; }
  double Duration() const override { return duration_s_; }
  // The run-in holds the command of t = 0, so the schedule starts from its own steady state.
  std::vector<double> InitialCommand() const override {
    std::vector<double> u(inputs_);
    command_(0.0, u);
    return u;
  }
  void Command(double t, std::span<const double>, std::span<double> u) override { command_(t, u); }

  std::unique_ptr<Maneuver> Clone() const override { return std::make_unique<InputSchedule>(*this); }

 private:
  std::string spec_;
  double duration_s_;
  int inputs_;
  std::function<void(double, std::span<double>)> command_;
};

// Piecewise-constant random levels, uniform in each input's excitation range; hold times
// uniform in [hold_s / 2, 3 hold_s / 2] for yaw and side inputs, four times longer for thrust.
std::unique_ptr<Maneuver> MakeRandomSteps(const Actuation& act, double hold_s, double duration_s,
                                          uint64_t seed);

// Maximum-length pseudo-random binary sequences (10-bit LFSR), one per excited input with its
// own start, clock period `clock_s` (thrust: 5 x clock_s), between 15 % and 85 % of the range.
std::unique_ptr<Maneuver> MakePrbs(const Actuation& act, double clock_s, double duration_s,
                                   uint64_t seed);

// Random-phase multisines over the harmonics of 1 / duration up to f_max_hz (thrust: f_max/10),
// scaled to span 90 % of each excitation range.
std::unique_ptr<Maneuver> MakeMultisine(const Actuation& act, double f_max_hz, double duration_s,
                                        uint64_t seed);

}  // namespace usvid
