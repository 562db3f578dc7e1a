#include "simulation/segment_error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

#include "core/error.h"
#include "core/stretches.h"
#include "simulation/divergence_bounds.h"

namespace usvid {
namespace {

using SegmentRows = std::pair<Eigen::Index, Eigen::Index>;  // [first, last]

// Each channel's variance over the data (over its sampled rows), at least 1e-300.
std::vector<double> SegmentChannelVariances(const Dataset& data,
                                            const std::vector<std::string>& channels) {
  std::vector<double> variance;
  for (const std::string& c : channels) {
    const Eigen::ArrayXd v = data[c].array();
    if (v.allFinite()) {
      variance.push_back(std::max((v - v.mean()).square().mean(), 1e-300));
    } else {  // over the sampled rows
      const auto sampled = v.isFinite();
      const auto n = static_cast<double>(std::max<Eigen::Index>(1, sampled.count()));
      const double mean = sampled.select(v, 0.0).sum() / n;
      variance.push_back(std::max(sampled.select((v - mean).square(), 0.0).sum() / n, 1e-300));
    }
  }
  return variance;
}

// The segments: [first, last] rows, within segment_s and across no gap; each run from its
// first row's measured state.
std::vector<SegmentRows> SegmentsWithin(const Dataset& data, double segment_s) {
  std::vector<SegmentRows> segments;
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
    segments.emplace_back(start, end);
    start = end;
  }
  return segments;
}

// The order the segments run in: the data's, or the largest likely error first (a guess of NaN,
// a segment the similar model left unrun, last).
std::vector<size_t> SegmentRunOrder(size_t count, const std::vector<double>& likely) {
  std::vector<size_t> order(count);
  std::iota(order.begin(), order.end(), size_t{0});
  if (likely.size() != count) return order;
  const auto guess = [&](size_t s) {
    return std::isnan(likely[s]) ? -std::numeric_limits<double>::infinity() : likely[s];
  };
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return guess(a) > guess(b); });
  return order;
}

// Runs one segment open-loop from its first row: its squared errors over the variances, in the
// order they are summed, go to `terms`; true when the run stopped early or left the bounds.
bool RunOneSegment(const VesselSimulator& sim, const std::vector<double>& params,
                   const EffectValues<double>& effects, const Dataset& data,
                   const std::vector<std::string>& channels, const std::vector<double>& variance,
                   const RunOptions& options, SegmentRows rows, std::vector<double>& terms) {
  std::vector<bool> keep(data.rows(), false);
  for (Eigen::Index i = rows.first; i <= rows.second; ++i) keep[i] = true;
  Dataset segment = data;
  segment.KeepRows(keep);
  const SimulationResult r = sim.RunInputs(segment, params, effects, options);
  std::vector<const Eigen::VectorXd*> simulated;
  if (r.data.rows() > 0)
    for (const std::string& c : channels) simulated.push_back(&r.data[c]);
  bool diverged = r.data.rows() < segment.rows();
  const DivergenceBounds bounds(channels, segment);
  Eigen::VectorXd x(static_cast<Eigen::Index>(channels.size()));
  for (Eigen::Index k = 0; k < r.data.rows() && !diverged; ++k) {
    for (size_t c = 0; c < channels.size(); ++c)
      x(static_cast<Eigen::Index>(c)) = (*simulated[c])(k);
    diverged = bounds.Exceeded(x) >= 0;
  }
  for (size_t c = 0; c < channels.size(); ++c) {
    const Eigen::VectorXd& y = segment[channels[c]];
    for (Eigen::Index k = 0; k < segment.rows(); ++k) {
      if (!std::isfinite(y(k))) continue;  // not sampled there
      const double e = k < r.data.rows() ? (*simulated[c])(k)-y(k) : y(k);
      terms.push_back(e * e / variance[c]);
    }
  }
  return diverged;
}

}  // namespace

SegmentedError SegmentedSimulationErrorOf(const VesselSimulator& sim,
                                          const std::vector<double>& params,
                                          const EffectValues<double>& effects, const Dataset& data,
                                          const std::vector<std::string>& channels,
                                          double segment_s, const RunOptions& options,
                                          const SegmentStop& stop) {
  if (!(segment_s > 0)) throw InputError("segment length must be positive");
  const std::vector<double> variance = SegmentChannelVariances(data, channels);
  const std::vector<SegmentRows> segments = SegmentsWithin(data, segment_s);
  // The rows the error averages over, known before any run: each segment's sampled values.
  long count = 0;
  for (const auto& [first, last] : segments)
    for (const std::string& c : channels)
      count += data[c].segment(first, last - first + 1).array().isFinite().count();
  const std::vector<size_t> order = SegmentRunOrder(segments.size(), stop.likely_errors);
  // Run out of the data's order, each segment's squared errors over the variances are kept, to be
  // summed in the data's order once all have run.
  const bool reordered = !std::is_sorted(order.begin(), order.end());
  std::vector<std::vector<double>> terms(reordered ? segments.size() : 0);
  SegmentedError out;
  out.segment_errors.assign(segments.size(), std::numeric_limits<double>::quiet_NaN());
  double so_far = 0.0;  // in the order run
  for (const size_t s : order) {
    if ((out.diverged && stop.at_divergence) ||
        (count > 0 && so_far / static_cast<double>(count) > stop.above)) {
      out.stopped = true;
      break;
    }
    std::vector<double> segment_terms;
    const bool diverged = RunOneSegment(sim, params, effects, data, channels, variance, options,
                                        segments[s], segment_terms);
    out.diverged = out.diverged || diverged;
    double sum = 0.0;
    for (const double term : segment_terms) {
      so_far += term;
      sum += term;
    }
    out.segment_errors[s] = count > 0 ? sum / static_cast<double>(count) : 0.0;
    if (reordered) terms[s] = std::move(segment_terms);
  }
  // A finished run's total is summed in the data's order, whatever order the segments ran in (in
  // the data's order, so_far is that sum); a stopped one's is what its segments add.
  double total = so_far;
  if (reordered && !out.stopped) {
    total = 0.0;
    for (const std::vector<double>& kept : terms)
      for (const double term : kept) total += term;
  }
  out.error = count > 0 ? total / static_cast<double>(count) : 0.0;
  return out;
}

double SegmentedSimulationError(const VesselSimulator& sim, const std::vector<double>& params,
                                const EffectValues<double>& effects, const Dataset& data,
                                const std::vector<std::string>& channels, double segment_s,
                                const RunOptions& options) {
  return SegmentedSimulationErrorOf(sim, params, effects, data, channels, segment_s, options).error;
}

}  // namespace usvid
