#include "preprocessing/pipeline.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/error.h"
#include "core/stretches.h"

namespace usvid {
namespace {

// The fewest rows a stretch between gaps needs to be smoothed and differentiated.
constexpr Eigen::Index kMinStretchRows = 10;

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

// u(t - delay) on the same grid (zero-order hold, each stretch's first value before its start:
// no input crosses a gap).
Eigen::VectorXd Shift(const Eigen::VectorXd& u, int samples,
                      const std::vector<Stretch>& stretches) {
  Eigen::VectorXd out(u.size());
  for (const Stretch& s : stretches)
    for (Eigen::Index k = s.first; k < s.end; ++k)
      out(k) = u(std::max<Eigen::Index>(s.first, k - samples));
  return out;
}

// The stretches of consecutive kept rows, as rows of the grid after the others are dropped.
std::vector<Stretch> KeptStretches(const std::vector<bool>& keep) {
  std::vector<Stretch> out;
  Eigen::Index at = 0;
  bool open = false;
  for (const bool k : keep) {
    if (k && !open) out.push_back({at, at});
    if (k) out.back().end = ++at;
    open = k;
  }
  return out;
}

// Each stretch smoothed and differentiated on its own, with the breaks inside it.
SmoothedSignal SmoothStretches(const Eigen::VectorXd& y, double dt, const DerivativeMethod& method,
                               const std::vector<Stretch>& stretches,
                               const std::vector<Eigen::Index>& breaks) {
  if (stretches.size() == 1) return SmoothAndDifferentiate(y, dt, method, breaks);
  SmoothedSignal out{Eigen::VectorXd(y.size()), Eigen::VectorXd(y.size())};
  for (const Stretch& s : stretches) {
    std::vector<Eigen::Index> inside;
    for (const Eigen::Index b : breaks)
      if (b > s.first && b < s.end) inside.push_back(b - s.first);
    const SmoothedSignal piece =
        SmoothAndDifferentiate(y.segment(s.first, s.rows()), dt, method, inside);
    out.value.segment(s.first, s.rows()) = piece.value;
    out.derivative.segment(s.first, s.rows()) = piece.derivative;
  }
  return out;
}

// The grid's rows that have every used channel, in stretches of at least kMinStretchRows (the
// shorter ones dropped and counted in `short_stretches`).
std::vector<bool> RowsToKeep(const Dataset& grid, const std::vector<std::string>& states,
                             const std::vector<std::string>& inputs, long& short_stretches) {
  std::vector<bool> keep(grid.rows(), true);
  for (const auto& names : {states, inputs})
    for (const std::string& n : names)
      for (Eigen::Index k = 0; k < grid.rows(); ++k) keep[k] = keep[k] && grid.Get(n).IsSampled(k);
  short_stretches = 0;
  for (Eigen::Index k = 0; k < grid.rows();) {
    if (!keep[k]) {
      ++k;
      continue;
    }
    Eigen::Index end = k;
    while (end < grid.rows() && keep[end]) ++end;
    if (end - k < kMinStretchRows) {
      std::fill(keep.begin() + k, keep.begin() + end, false);
      ++short_stretches;
    }
    k = end;
  }
  return keep;
}

// The grid points left out that lie between records, or in a dropout of the whole log: no data
// lost, counted apart.
long BetweenRecords(const Dataset& data, const Dataset& grid, const std::vector<bool>& keep) {
  long between = 0;
  const std::vector<Stretch> raw = Stretches(data.t(), kRawGapFactor);
  size_t s = 0;
  for (Eigen::Index k = 0; k < grid.rows(); ++k) {
    const double t = grid.t()(k);
    while (s + 1 < raw.size() && t >= data.t()(raw[s + 1].first)) ++s;
    if (!keep[k] && t > data.t()(raw[s].end - 1)) ++between;
  }
  return between;
}

// The input delay by the equation-error scan, on derivatives without breaks (the breaks depend
// on the delay).
DelayEstimate EstimateDelay(const Dataset& grid, const std::vector<std::string>& states,
                            const std::vector<std::string>& inputs, double dt,
                            const std::vector<Stretch>& stretches,
                            const PreprocessOptions& options) {
  DelayProblem p;
  p.dt = dt;
  for (const std::string& s : states) {
    const SmoothedSignal sm = SmoothStretches(grid[s], dt, options.derivative, stretches, {});
    p.states.push_back({s, sm.value});
    p.derivatives.push_back({s + "_dot", sm.derivative});
  }
  for (const std::string& u : inputs) p.inputs.push_back({u, grid[u]});
  return ScanDelay(p, std::min(options.max_delay_s, 0.2 * grid.duration()));
}

// The rows where the (shifted) inputs step, within each stretch; none, with a note, when the
// steps leave half the record in pieces under options.min_piece_s (inputs not piecewise
// constant).
std::vector<Eigen::Index> InputStepBreaks(const std::vector<Eigen::VectorXd>& shifted,
                                          const std::vector<Stretch>& stretches, Eigen::Index rows,
                                          double dt, const PreprocessOptions& options,
                                          std::vector<std::string>& notes) {
  std::vector<Eigen::Index> breaks;
  if (!options.step_breaks) return breaks;
  for (const Stretch& st : stretches) {
    std::vector<Eigen::VectorXd> piece;
    for (const Eigen::VectorXd& u : shifted) piece.push_back(u.segment(st.first, st.rows()));
    for (const Eigen::Index b : StepBreaks(piece)) breaks.push_back(st.first + b);
  }
  if (breaks.empty()) return breaks;
  std::vector<Eigen::Index> edges = breaks;  // the stretches' ends cut pieces too
  for (const Stretch& st : stretches)
    if (st.first > 0) edges.push_back(st.first);
  std::ranges::sort(edges);
  const double typical_s = static_cast<double>(TypicalPiece(edges, rows)) * dt;
  if (typical_s < options.min_piece_s) {
    std::ostringstream d;
    d << "no step breaks: the inputs' " << breaks.size()
      << " changes leave half the record in stretches under " << typical_s
      << " s, so they are not piecewise constant";
    notes.push_back(d.str());
    breaks.clear();
  }
  return breaks;
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
  // Rows where any used channel is missing (ends, long gaps) are dropped, and stretches too short
  // to differentiate.
  long short_stretches = 0;
  const std::vector<bool> keep = RowsToKeep(grid, states, inputs, short_stretches);
  const long between = BetweenRecords(data, grid, keep);
  const long dropped = std::count(keep.begin(), keep.end(), false) - between;
  const std::vector<Stretch> stretches = KeptStretches(keep);
  if (dropped + between > 0) grid.KeepRows(keep);
  if (grid.rows() < 10) throw InputError("preprocess: fewer than 10 rows have every channel");
  const double dt = 1.0 / ro.rate_hz;
  std::ostringstream note;
  note << "resampled to " << ro.rate_hz << " Hz ("
       << (ro.interpolation == Interpolation::kLinear ? "linear" : "cubic spline") << "), "
       << grid.rows() << " rows";
  if (dropped > 0) note << ", " << dropped << " rows without every channel dropped";
  if (short_stretches > 0)
    note << " (with " << short_stretches << " stretches under " << kMinStretchRows << " rows)";
  if (stretches.size() > 1)
    note << "; " << stretches.size()
         << " stretches between gaps or records, each smoothed and differentiated on its own";
  out.notes.push_back(note.str());

  out.delay_s = options.delay_s;
  if (options.estimate_delay) {
    out.delay_estimate = EstimateDelay(grid, states, inputs, dt, stretches, options);
    out.delay_s = out.delay_estimate->delay_s;
    std::ostringstream d;
    d << "input delay estimated by the equation-error scan: " << out.delay_s << " s";
    out.notes.push_back(d.str());
  }
  if (out.delay_s < 0) throw InputError("--delay: must not be negative");
  const int shift = static_cast<int>(std::lround(out.delay_s / dt));

  Dataset result(grid.t());
  std::vector<Eigen::VectorXd> shifted;
  for (const std::string& u : inputs) shifted.push_back(Shift(grid[u], shift, stretches));
  const std::vector<Eigen::Index> breaks =
      InputStepBreaks(shifted, stretches, grid.rows(), dt, options, out.notes);
  for (const std::string& s : states) {
    const SmoothedSignal sm = SmoothStretches(grid[s], dt, options.derivative, stretches, breaks);
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
