#include "simulation/characterisation.h"

#include <cmath>

#include "core/error.h"
#include "maneuvers/excitation.h"
#include "maneuvers/input_schedule.h"

namespace usvid {

std::vector<SteadyPoint> SteadySweep(const VesselSimulator& sim, const std::vector<double>& params,
                                     int points, double yaw_command) {
  const Actuation& act = sim.Info().actuation;
  if (act.thrust_input < 0 || act.speed_state < 0)
    throw InputError("vessel " + sim.Info().name + " has no thrust input and speed");
  RunOptions options;
  options.run_in_s = 1200.0;
  const double lo = act.input_min[act.thrust_input], hi = act.input_max[act.thrust_input];
  const double base = std::max(lo, 0.0);
  std::vector<SteadyPoint> sweep;
  for (int k = 0; k < points; ++k) {
    SteadyPoint p;
    p.thrust = points == 1 ? hi : base + (hi - base) * k / (points - 1);
    p.yaw = yaw_command;
    std::vector<double> u = CruiseCommand(act);
    u[act.thrust_input] = p.thrust;
    u[act.yaw_input] = yaw_command;
    InputSchedule hold("hold", 0.0, act.inputs(), [u](double, std::span<double> out) {
      std::copy(u.begin(), u.end(), out.begin());
    });
    const SimulationResult r = sim.RunManeuver(hold, params, {}, options);
    std::vector<double> state;
    for (const std::string& s : sim.Info().states) state.push_back(r.data[s](0));
    p.speed = act.Speed(state);
    p.rate = state[act.rate_state];
    p.radius = std::abs(p.rate) > 1e-6 ? p.speed / std::abs(p.rate) : 0.0;
    p.settled = r.run_in_s < options.run_in_s;
    sweep.push_back(p);
  }
  return sweep;
}

}  // namespace usvid
