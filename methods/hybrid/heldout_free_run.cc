#include "methods/hybrid/heldout_free_run.h"

#include <cmath>
#include <limits>

#include "core/records.h"
#include "effects/effect_values.h"
#include "simulation/divergence_bounds.h"
#include "simulation/vessel_simulator.h"

namespace usvid::hybrid {

double HeldoutFreeRunError(const std::string& vessel, const Dataset& heldout,
                           const std::vector<double>& params, const std::vector<Effect>& terms,
                           const std::vector<std::string>& states) {
  constexpr double kDiverged = std::numeric_limits<double>::infinity();
  const VesselSimulator& simulator = FindVessel(vessel);
  const VesselInfo& info = simulator.Info();
  const EffectValues<double> effects = ValuesOf(terms, info.inputs, info.states);
  const std::vector<long> starts = RecordStarts(heldout.t());
  std::vector<double> squared(states.size(), 0.0), sum(states.size(), 0.0),
      sum_squares(states.size(), 0.0);
  std::vector<long> samples(states.size(), 0);
  for (size_t k = 0; k < starts.size(); ++k) {
    const long end = k + 1 < starts.size() ? starts[k + 1] : static_cast<long>(heldout.rows());
    const Dataset record = heldout.Rows(starts[k], end - starts[k]);
    const SimulationResult run = simulator.RunInputs(record, params, effects, RunOptions{});
    if (run.diverged || run.data.rows() != record.rows()) return kDiverged;
    const DivergenceBounds bounds(states, record);
    Eigen::VectorXd x(static_cast<Eigen::Index>(states.size()));
    for (Eigen::Index row = 0; row < record.rows(); ++row) {
      for (size_t s = 0; s < states.size(); ++s)
        x(static_cast<Eigen::Index>(s)) = run.data[states[s]](row);
      if (bounds.Exceeded(x) >= 0) return kDiverged;
      for (size_t s = 0; s < states.size(); ++s) {
        // Compared where the state was measured (a sensor's own rate, a dropout: not sampled).
        const double measured = record.Get(states[s]).Value(row);
        if (!std::isfinite(measured)) continue;
        squared[s] += std::pow(x(static_cast<Eigen::Index>(s)) - measured, 2);
        sum[s] += measured;
        sum_squares[s] += measured * measured;
        ++samples[s];
      }
    }
  }
  double error = 0.0;
  int compared = 0;
  for (size_t s = 0; s < states.size(); ++s) {
    if (samples[s] == 0) continue;
    const auto n = static_cast<double>(samples[s]);
    const double variance = std::max(sum_squares[s] / n - std::pow(sum[s] / n, 2), 1e-12);
    error += squared[s] / n / variance;
    ++compared;
  }
  return compared > 0 ? error / compared : 0.0;
}

}  // namespace usvid::hybrid
