#include "methods/hybrid/heldout_free_run.h"

#include <limits>
#include <utility>

#include "effects/effect_values.h"
#include "simulation/segment_error.h"
#include "simulation/vessel_simulator.h"

namespace usvid::hybrid {

HeldoutFreeRun HeldoutFreeRuns(const VesselRef& vessel, const Dataset& heldout,
                               const std::vector<double>& params, const std::vector<Effect>& terms,
                               const std::vector<std::string>& states, double stop_above,
                               const std::vector<double>& likely) {
  const VesselSimulator& simulator = vessel.Simulator();
  const VesselInfo& info = simulator.Info();
  // One segment per stretch between gaps: each record (core/records.h) is one free run.
  SegmentedError run = SegmentedSimulationErrorOf(
      simulator, params, ValuesOf(terms, info.inputs, info.states), heldout, states,
      std::numeric_limits<double>::infinity(), {},
      SegmentStop{.at_divergence = true, .above = stop_above, .likely_errors = likely});
  return {run.diverged ? std::numeric_limits<double>::infinity() : run.error,
          std::move(run.segment_errors)};
}

double HeldoutFreeRunError(const VesselRef& vessel, const Dataset& heldout,
                           const std::vector<double>& params, const std::vector<Effect>& terms,
                           const std::vector<std::string>& states, double stop_above) {
  return HeldoutFreeRuns(vessel, heldout, params, terms, states, stop_above).error;
}

}  // namespace usvid::hybrid
