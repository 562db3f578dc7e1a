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
  long rows = 0;
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
        const double measured = record[states[s]](row);
        squared[s] += std::pow(x(static_cast<Eigen::Index>(s)) - measured, 2);
        sum[s] += measured;
        sum_squares[s] += measured * measured;
      }
    }
    rows += record.rows();
  }
  double error = 0.0;
  for (size_t s = 0; s < states.size(); ++s) {
    const double mean = sum[s] / static_cast<double>(rows);
    const double variance =
        std::max(sum_squares[s] / static_cast<double>(rows) - mean * mean, 1e-12);
    error += squared[s] / static_cast<double>(rows) / variance;
  }
  return error / static_cast<double>(states.size());
}

}  // namespace usvid::hybrid
