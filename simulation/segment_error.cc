#include "simulation/segment_error.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/stretches.h"

namespace usvid {

double SegmentedSimulationError(const VesselSimulator& sim, const std::vector<double>& params,
                                const EffectValues<double>& effects, const Dataset& data,
                                const std::vector<std::string>& channels, double segment_s,
                                const RunOptions& options) {
  if (!(segment_s > 0)) throw InputError("segment length must be positive");
  std::vector<double> variance;
  for (const std::string& c : channels) {
    const Eigen::ArrayXd v = data[c].array();
    variance.push_back(std::max((v - v.mean()).square().mean(), 1e-300));
  }
  double total = 0.0;
  long count = 0;
  const Eigen::VectorXd& t = data.t();
  const double gap = GapLimit(t, kRawGapFactor);  // no segment runs across a gap
  Eigen::Index start = 0;
  while (start + 1 < data.rows()) {
    if (t(start + 1) - t(start) > std::min(gap, segment_s)) {
      ++start;
      continue;
    }
    Eigen::Index end = start;
    while (end + 1 < data.rows() && t(end + 1) - t(start) <= segment_s &&
           t(end + 1) - t(end) <= gap)
      ++end;
    std::vector<bool> keep(data.rows(), false);
    for (Eigen::Index i = start; i <= end; ++i) keep[i] = true;
    Dataset segment = data;
    segment.KeepRows(keep);
    const SimulationResult r = sim.RunInputs(segment, params, effects, options);
    for (size_t c = 0; c < channels.size(); ++c) {
      const Eigen::VectorXd& y = segment[channels[c]];
      for (Eigen::Index k = 0; k < segment.rows(); ++k) {
        const double e = k < r.data.rows() ? r.data[channels[c]](k) - y(k) : y(k);
        total += e * e / variance[c];
      }
    }
    count += static_cast<long>(segment.rows() * channels.size());
    start = end;
  }
  return count > 0 ? total / static_cast<double>(count) : 0.0;
}

}  // namespace usvid
