// Runs a maneuver on a vessel with effects (double precision). Before t = 0 the vessel is
// brought to steady state under the maneuver's initial command (run-in), then positions and
// heading are zeroed. From t = 0 the maneuver is asked for a command at every output tick
// (1 / rate_hz), which is held until the next tick; between ticks the plant is integrated in
// equal substeps of at most dt, each seeing the command in force at (its start - delay).
// Rows record the state at the tick and the command issued there, so replaying the recorded
// commands open-loop (open_loop.h) reproduces the run exactly.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "maneuvers/maneuver.h"
#include "simulation/input_track.h"
#include "simulation/plant_stepper.h"
#include "simulation/run_options.h"

namespace usvid {

struct ClosedLoopRun {
  std::vector<double> times;
  std::vector<double> states;  // rows x V::kStates
  InputTrack commands{0};
  double run_in_s = 0.0;  // how long the run-in took
  bool diverged = false;
};

// Indices of the states zeroed after the run-in (positions and heading).
struct KinematicStates {
  int north = -1, east = -1, heading = -1;
};

template <Vessel V>
ClosedLoopRun RunClosedLoop(Maneuver& maneuver, const std::array<double, V::kParams>& params,
                            const EffectValues<double>& effects,
                            const std::array<double, V::kInputs>& limits,
                            const KinematicStates& kinematic, const RunOptions& opt) {
  constexpr int N = Plant<V>::kStates;
  std::array<double, V::kParams> p_eff;
  Plant<V>::ScaleParams(params.data(), effects, p_eff.data());
  // The effects the plant sees: a disturbance's accelerations change them at every period.
  EffectValues<double> live = effects;
  PlantStepper<V, double> stepper{p_eff.data(), &live, limits, opt.integrator, {}};
  const double delay = TotalDelay<V>(effects.delay_s);
  const double period = 1.0 / opt.rate_hz;
  const int substeps = std::max(1, static_cast<int>(std::ceil(period / opt.dt - 1e-9)));
  const double h = period / substeps;

  ClosedLoopRun run;
  run.commands = InputTrack(V::kInputs);
  typename PlantStepper<V, double>::State x = PlantStepper<V, double>::State::Zero();
  const std::vector<double> u0 = maneuver.InitialCommand();
  Plant<V>::InitialLagState(u0.data(), x.data());

  // Run-in: hold the initial command until the non-kinematic states settle.
  auto settled_states = [&](const auto& a, const auto& b) {
    for (int i = 0; i < N; ++i) {
      if (i == kinematic.north || i == kinematic.east || i == kinematic.heading) continue;
      if (std::abs(a(i) - b(i)) > 1e-7 * (1.0 + std::abs(a(i)))) return false;
    }
    return true;
  };
  // A large ship needs longer than the default to reach its speed from rest (kvlcc2: its surge
  // time constant is about 5 minutes).
  double run_in = opt.run_in_s;
  if constexpr (requires { V::kRunInS; }) run_in = std::max(run_in, V::kRunInS);
  for (double t = 0; t < run_in; t += 1.0) {
    const auto before = x;
    for (int s = 0; s < static_cast<int>(std::round(1.0 / h)); ++s) stepper.Step(u0.data(), h, x);
    run.run_in_s = t + 1.0;
    if (settled_states(before, x)) break;
  }
  for (int i : {kinematic.north, kinematic.east, kinematic.heading})
    if (i >= 0) x(i) = 0.0;
  for (int i = 0; i < V::kStates && i < static_cast<int>(opt.initial_state.size()); ++i)
    if (std::isfinite(opt.initial_state[i]) && i != kinematic.north && i != kinematic.east &&
        i != kinematic.heading)
      x(i) = opt.initial_state[i];

  // A disturbance acts from t = 0 (the run-in is calm: the wind rises as the record starts).
  auto disturb = [&](double t) {
    if (!opt.disturbance) return;
    const std::array<double, 3> a =
        opt.disturbance(t, std::span<const double>(x.data(), V::kStates));
    live.surge_acceleration = effects.surge_acceleration + a[0];
    live.sway_acceleration = effects.sway_acceleration + a[1];
    live.yaw_acceleration = effects.yaw_acceleration + a[2];
  };
  std::vector<double> u(V::kInputs);
  InputTrack::Cursor cursor;
  const long ticks = static_cast<long>(std::floor(maneuver.Duration() * opt.rate_hz + 1e-9)) + 1;
  for (long k = 0; k < ticks; ++k) {
    const double t = k * period;
    maneuver.Command(t, std::span<const double>(x.data(), V::kStates), u);
    run.commands.Append(t, u);
    run.times.push_back(t);
    for (int i = 0; i < V::kStates; ++i) run.states.push_back(x(i));
    if (maneuver.Done() || k + 1 == ticks) break;
    disturb(t);
    std::array<double, V::kInputs> cmd;
    for (int s = 0; s < substeps; ++s) {
      run.commands.Delayed(t + s * h, delay, effects.input_delays_s, cmd.data(), cursor);
      stepper.Step(cmd.data(), h, x);
    }
    if (!x.allFinite() || x.cwiseAbs().maxCoeff() > 1e7) {
      run.diverged = true;
      break;
    }
  }
  return run;
}

}  // namespace usvid
