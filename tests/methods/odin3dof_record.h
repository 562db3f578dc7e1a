// A test fixture shared by the grey-box identifications' tests (hybrid, GP's --base): odin3dof's
// random steps with effects the vessel lacks, 0.5 % noise on its states, and the cross-flow yaw
// term r' += 0.05 |v| v that the vessel lacks in them.
#pragma once

#include <vector>

#include "effects/effect.h"
#include "effects/effect_values.h"
#include "maneuvers/maneuver_factory.h"
#include "sensors/noise.h"
#include "simulation/vessel_simulator.h"

namespace usvid::fixtures {

inline Dataset Odin3dofRandomSteps(const std::vector<Effect>& effects, double seconds,
                                   uint64_t seed) {
  const VesselSimulator& sim = FindVessel("odin3dof");
  const VesselInfo& info = sim.Info();
  auto m = MakeManeuver("random-steps", info.actuation, seconds, seed);
  Dataset d = sim.RunManeuver(*m, info.default_params, ValuesOf(effects, info.inputs, info.states),
                              RunOptions{})
                  .data;
  AddGaussianNoise(d, info.states, 0.005, seed);
  return d;
}

inline const Effect kCrossFlowYaw{
    EffectKind::kMissingTerm, {{"coefficient", 0.05}}, {}, "r", "abs(v)*v"};

}  // namespace usvid::fixtures
