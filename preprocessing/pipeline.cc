#include "preprocessing/pipeline.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/error.h"

namespace usvid {
namespace {

// The length, in samples, of the stretch between breaks that the median sample lies in: half
// the record is in stretches at least this long. A ramp's many breaks close together weigh
// little beside the long holds around them; a quantised or hand-moved input's breaks everywhere
// make it short.
Eigen::Index TypicalPiece(const std::vector<Eigen::Index>& breaks, Eigen::Index rows) {
  std::vector<Eigen::Index> pieces;
  Eigen::Index previous = 0;
  for (const Eigen::Index b : breaks) {
    pieces.push_back(b - previous);
    previous = b;
  }
  pieces.push_back(rows - previous);
  std::sort(pieces.begin(), pieces.end());
  Eigen::Index covered = 0;
  for (const Eigen::Index p : pieces)
    if ((covered += p) * 2 >= rows) return p;
  return pieces.back();
}

// The data's own rate: one over the median interval between rows.
double NativeRate(const Dataset& d) { return 1.0 / MedianInterval(d.t()); }

// u(t - delay) on the same grid (zero-order hold, the first value before the start).
Eigen::VectorXd Shift(const Eigen::VectorXd& u, int samples) {
  Eigen::VectorXd out(u.size());
  for (Eigen::Index k = 0; k < u.size(); ++k) out(k) = u(std::max<Eigen::Index>(0, k - samples));
  return out;
}

}  // namespace

PreparedData Preprocess(const Dataset& data, const std::vector<std::string>& states,
                        const std::vector<std::string>& inputs, const PreprocessOptions& options) {
  if (data.rows() < 10) throw InputError("preprocess: the data need at least 10 rows");
  for (const auto& names : {states, inputs})
    for (const std::string& n : names)
      if (!data.Has(n)) {
        data.CheckNotText(n);
        throw InputError("preprocess: no channel '" + n + "' in the data");
      }
  PreparedData out;
  ResampleOptions ro;
  ro.rate_hz = options.rate_hz > 0 ? options.rate_hz : NativeRate(data);
  ro.interpolation = options.interpolation;
  // Only the channels used: a long log's other channels are not copied onto the grid.
  ro.channels = states;
  ro.channels.insert(ro.channels.end(), inputs.begin(), inputs.end());
  ResampleReport report;
  Dataset grid = Resample(data, ro, &report);
  // Rows where any used channel is missing (ends, long gaps) are dropped.
  std::vector<bool> keep(grid.rows(), true);
  for (const auto& names : {states, inputs})
    for (const std::string& n : names)
      for (Eigen::Index k = 0; k < grid.rows(); ++k) keep[k] = keep[k] && grid.Get(n).sampled(k);
  const long dropped = std::count(keep.begin(), keep.end(), false);
  if (dropped > 0) grid.KeepRows(keep);
  if (grid.rows() < 10) throw InputError("preprocess: fewer than 10 rows have every channel");
  const double dt = 1.0 / ro.rate_hz;
  std::ostringstream note;
  note << "resampled to " << ro.rate_hz << " Hz ("
       << (ro.interpolation == Interpolation::kLinear ? "linear" : "cubic spline") << "), "
       << grid.rows() << " rows";
  if (dropped > 0) note << ", " << dropped << " rows without every channel dropped";
  out.notes.push_back(note.str());

  // Delay: estimated on derivatives without breaks (the breaks depend on the delay).
  out.delay_s = options.delay_s;
  if (options.estimate_delay) {
    DelayProblem p;
    p.dt = dt;
    for (const std::string& s : states) {
      const SmoothedSignal sm = SmoothAndDifferentiate(grid[s], dt, options.derivative);
      p.states.push_back({s, sm.value});
      p.derivatives.push_back({s + "_dot", sm.derivative});
    }
    for (const std::string& u : inputs) p.inputs.push_back({u, grid[u]});
    out.delay_estimate = ScanDelay(p, std::min(options.max_delay_s, 0.2 * grid.duration()));
    out.delay_s = out.delay_estimate->delay_s;
    std::ostringstream d;
    d << "input delay estimated by the equation-error scan: " << out.delay_s << " s";
    out.notes.push_back(d.str());
  }
  if (out.delay_s < 0) throw InputError("--delay: must not be negative");
  const int shift = static_cast<int>(std::lround(out.delay_s / dt));

  Dataset result(grid.t());
  std::vector<Eigen::VectorXd> shifted;
  for (const std::string& u : inputs) shifted.push_back(Shift(grid[u], shift));
  std::vector<Eigen::Index> breaks =
      options.step_breaks ? StepBreaks(shifted) : std::vector<Eigen::Index>{};
  if (!breaks.empty()) {
    const double typical_s = static_cast<double>(TypicalPiece(breaks, grid.rows())) * dt;
    if (typical_s < options.min_piece_s) {
      std::ostringstream d;
      d << "no step breaks: the inputs' " << breaks.size()
        << " changes leave half the record in stretches under " << typical_s
        << " s, so they are not piecewise constant";
      out.notes.push_back(d.str());
      breaks.clear();
    }
  }
  for (const std::string& s : states) {
    const SmoothedSignal sm = SmoothAndDifferentiate(grid[s], dt, options.derivative, breaks);
    result.Set(s, sm.value);
    result.Set(s + "_dot", sm.derivative);
    result.Set(s + "_raw", grid[s]);
  }
  for (size_t i = 0; i < inputs.size(); ++i) result.Set(inputs[i], shifted[i]);
  std::ostringstream d;
  d << "derivatives by " << options.derivative.Spec();
  if (!breaks.empty()) d << " with " << breaks.size() << " step breaks";
  if (shift > 0) d << "; inputs shifted by " << shift << " samples (" << shift * dt << " s)";
  out.notes.push_back(d.str());
  result.metadata() = data.metadata();
  out.data = std::move(result);
  return out;
}

}  // namespace usvid
