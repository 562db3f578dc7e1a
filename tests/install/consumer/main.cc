// Simulates odin3dof's random steps with the installed library and prints the top speed.
#include <iostream>

#include "maneuvers/maneuver_factory.h"
#include "simulation/vessel_simulator.h"

int main() {
  const usvid::VesselSimulator& sim = usvid::FindVessel("odin3dof");
  auto maneuver = usvid::MakeManeuver("random-steps", sim.Info().actuation, 60.0, 1);
  const auto result =
      sim.RunManeuver(*maneuver, sim.Info().default_params, {}, usvid::RunOptions{});
  std::cout << "odin3dof: " << result.data.rows() << " rows, top speed "
            << result.data["u"].maxCoeff() << " m/s\n";
  return result.diverged ? 1 : 0;
}
