#include "diagnosis/measured_data.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "core/error.h"
#include "preprocessing/smoothing_spline.h"
#include "simulation/recorded_inputs.h"
#include "simulation/segment_length.h"

namespace usvid::diagnosis {
namespace {

// Segment starts from `begin`, one every segment_s seconds, each moved forward to the first row
// where every channel is sampled.
Part MakePart(const MeasuredData& d, Eigen::Index begin, Eigen::Index end, double segment_s) {
  Part part{begin, end, {}};
  auto all_sampled = [&d](Eigen::Index k) { return d.sampled.row(k).all(); };
  Eigen::Index k = begin;
  while (k < end) {
    while (k < end && !all_sampled(k)) ++k;
    if (k >= end) break;
    part.starts.push_back(k);
    const double t_next = d.times[k] + segment_s;
    while (k < end && d.times[k] < t_next - 1e-9) ++k;
  }
  if (part.starts.empty() || part.starts[0] != begin)
    part.starts.insert(part.starts.begin(), begin);
  return part;
}

// Whether a channel's samples move: one that never does (a bucket held open) has no fit to
// score.
bool Moves(const Channel& c, Eigen::Index rows) {
  std::vector<double> v;
  for (Eigen::Index k = 0; k < rows; ++k)
    if (c.IsSampled(k)) v.push_back(c.Value(k));
  const Eigen::Map<const Eigen::ArrayXd> a(v.data(), static_cast<Eigen::Index>(v.size()));
  const double sd = std::sqrt((a - a.mean()).square().mean());
  return sd > 1e-6 * (1.0 + a.abs().mean());
}

// Scored channels: the vessel's states that the data measure (with two samples or more) and
// that move. Throws InputError when there are none.
void ChooseChannels(const Dataset& data, const VesselInfo& info, MeasuredData& d) {
  d.state_channel.assign(info.states.size(), -1);
  for (size_t i = 0; i < info.states.size(); ++i) {
    const Channel* c = data.Find(info.states[i]);
    if (c == nullptr || c->SampleCount() < 2) continue;
    if (!Moves(*c, data.rows())) continue;
    d.state_channel[i] = static_cast<int>(d.channels.size());
    d.channels.push_back(info.states[i]);
    d.channel_state.push_back(static_cast<int>(i));
  }
  if (d.channels.empty()) {
    std::string states;
    for (const std::string& s : info.states) states += (states.empty() ? "" : ", ") + s;
    throw InputError(data.SourcePrefix() + "no state column of vessel " + info.name + " (" +
                     states + ")");
  }
}

// The scored channels' samples (0 where unsampled) and where they are sampled.
void CopyMeasurements(const Dataset& data, MeasuredData& d) {
  const auto n = data.rows();
  const auto channels = static_cast<Eigen::Index>(d.channels.size());
  d.measured = Eigen::MatrixXd::Zero(n, channels);
  d.sampled.resize(n, channels);
  for (Eigen::Index c = 0; c < channels; ++c) {
    const Channel& ch = data.Get(d.channels[c]);
    d.sampled.col(c) = ch.sampled();
    for (Eigen::Index k = 0; k < n; ++k)
      if (ch.IsSampled(k)) d.measured(k, c) = ch.Value(k);
  }
}

// Smoothed values for the resets, the heading unwrapped first, and each channel's noise sd
// (channels with fewer than 8 samples are left as measured, their noise 0).
void SmoothResets(const VesselInfo& info, MeasuredData& d) {
  const Eigen::Index n = d.measured.rows();
  const auto channels = static_cast<Eigen::Index>(d.channels.size());
  d.reset = d.measured;
  d.noise_sd.assign(channels, 0.0);
  for (Eigen::Index c = 0; c < channels; ++c) {
    std::vector<Eigen::Index> rows;
    for (Eigen::Index k = 0; k < n; ++k)
      if (d.sampled(k, c)) rows.push_back(k);
    if (rows.size() < 8) continue;
    Eigen::VectorXd y(static_cast<Eigen::Index>(rows.size()));
    for (size_t i = 0; i < rows.size(); ++i)
      y(static_cast<Eigen::Index>(i)) = d.measured(rows[i], c);
    const bool angle =
        info.actuation.heading_state >= 0 && d.channel_state[c] == info.actuation.heading_state;
    if (angle)
      for (Eigen::Index i = 1; i < y.size(); ++i)
        y(i) -= 2.0 * std::numbers::pi * std::round((y(i) - y(i - 1)) / (2.0 * std::numbers::pi));
    const double dt =
        (d.times[rows.back()] - d.times[rows.front()]) / static_cast<double>(rows.size() - 1);
    const SmoothingSplineResult s = SmoothingSpline(y, dt);
    for (size_t i = 0; i < rows.size(); ++i)
      d.reset(rows[i], c) = s.value(static_cast<Eigen::Index>(i));
    d.noise_sd[c] = s.noise_sd;
  }
}

// Split by time: the last heldout_fraction of the record is held out. On a record longer than
// max_fit_rows, the fits use the training part's last max_fit_rows and the scores the held-out
// part's first. Throws InputError when either part has fewer than 20 rows.
void SplitParts(const Dataset& data, double heldout_fraction, Eigen::Index max_fit_rows,
                MeasuredData& d) {
  const auto n = data.rows();
  const double split_t = d.times.front() + (1.0 - heldout_fraction) * data.duration();
  Eigen::Index split = 0;
  while (split < n && d.times[split] < split_t) ++split;
  constexpr Eigen::Index kMinRows = 20;
  if (split < kMinRows || n - split < kMinRows)
    throw InputError(data.SourcePrefix() + "too few rows to diagnose (" + std::to_string(n) +
                     "): need at least " + std::to_string(2 * kMinRows));
  d.all = MakePart(d, 0, n, d.segment_s);
  d.train = MakePart(d, 0, split, d.segment_s);
  d.heldout = MakePart(d, split, max_fit_rows > 0 ? std::min(n, split + max_fit_rows) : n,
                       d.segment_s);
  const Eigen::Index fit_begin =
      max_fit_rows > 0 ? std::max<Eigen::Index>(0, split - max_fit_rows) : 0;
  d.fit = fit_begin == 0 ? d.train : MakePart(d, fit_begin, split, d.segment_s);
}

// Scale: the RMS change of each channel from its segment's first row.
void ComputeScales(MeasuredData& d) {
  const auto channels = static_cast<Eigen::Index>(d.channels.size());
  d.scale.assign(channels, 0.0);
  for (Eigen::Index c = 0; c < channels; ++c) {
    double sum = 0.0, mean_abs = 0.0;
    long count = 0;
    for (size_t s = 0; s < d.all.starts.size(); ++s) {
      const auto [a, b] = SegmentRows(d.all, s);
      for (Eigen::Index k = a; k < b; ++k) {
        if (!d.sampled(k, c)) continue;
        const double change = d.measured(k, c) - d.measured(a, c);
        sum += change * change;
        mean_abs += std::abs(d.measured(k, c));
        ++count;
      }
    }
    const double rms = count > 0 ? std::sqrt(sum / count) : 0.0;
    const double floor = 1e-6 * (1.0 + (count > 0 ? mean_abs / count : 0.0));
    d.scale[c] = std::max(rms, floor);
  }
}

// Fallback for unmeasured states: the nominal free run, its last row held if it diverged.
void FallbackStates(const Dataset& data, const VesselSimulator& sim,
                    const std::vector<double>& nominal_params, MeasuredData& d) {
  const VesselInfo& info = sim.Info();
  const auto n = data.rows();
  RunOptions run;
  run.dt = d.max_step;  // as resolved above: options.max_step 0 means the data's interval
  const SimulationResult free = sim.RunInputs(data, nominal_params, {}, run);
  d.fallback_states = Eigen::MatrixXd::Zero(n, static_cast<Eigen::Index>(info.states.size()));
  for (size_t i = 0; i < info.states.size(); ++i) {
    const Eigen::VectorXd& x = free.data[info.states[i]];
    for (Eigen::Index k = 0; k < n; ++k)
      d.fallback_states(k, static_cast<Eigen::Index>(i)) =
          x.size() > 0 ? x(std::min(k, x.size() - 1)) : 0.0;
  }
}

}  // namespace

MeasuredData PrepareMeasuredData(const Dataset& data, const VesselSimulator& sim,
                                 const std::vector<double>& nominal_params,
                                 const SplitOptions& options) {
  const VesselInfo& info = sim.Info();
  const std::string where = data.SourcePrefix();
  if (!(options.segment_s >= 0)) throw InputError("--segment must be positive, or 0 for automatic");
  if (!(options.heldout_fraction > 0 && options.heldout_fraction < 1))
    throw InputError("--heldout must be between 0 and 1");
  MeasuredData d;
  d.vessel = info.name;
  d.times.assign(data.t().data(), data.t().data() + data.rows());
  d.segment_s = options.segment_s > 0 ? options.segment_s : AutomaticSegmentSeconds(data, info);
  if (options.max_step < 0) throw InputError("--dt must be positive, or 0 for the data's interval");
  d.max_step = options.max_step;
  if (d.max_step == 0.0) {
    const double dt = MedianInterval(data.t());
    d.max_step = dt > 0 ? std::min(0.05, dt) : 0.05;
  }

  // Commands, zero-order hold.
  d.inputs = RecordedInputs(data, info);
  for (size_t i = 0; i < info.inputs.size(); ++i) {
    const std::string& name = info.inputs[i];
    d.measured_input.push_back(info.IsMeasuredInput(i));
    if (d.measured_input.back() && !data.Has(name)) continue;  // no wind logged
    if (data.Get(name).SampleCount() == 0)
      throw InputError(where + "input column '" + name + "' is empty");
  }
  d.peak_command = d.inputs.PeakAbs();
  d.wind = info.wind_body && data.Has("wind_speed") && data.Get("wind_speed").SampleCount() > 0;
  // A logged wind is met on each segment's own heading (docs/model.md#wind-on-its-own-heading).
  if (d.wind)
    if (std::optional<InputTrack> air = WindOverGround(data, info, d.inputs)) {
      d.inputs = std::move(*air);
      d.base.wind_over_ground = true;
    }

  ChooseChannels(data, info, d);
  CopyMeasurements(data, d);
  SmoothResets(info, d);
  if (info.actuation.rate_state >= 0) d.rate_channel = d.state_channel[info.actuation.rate_state];
  if (info.actuation.heading_state >= 0)
    d.heading_channel = d.state_channel[info.actuation.heading_state];
  if (options.max_fit_rows < 0) throw InputError("--fit-rows: must be 0 (all) or more");
  SplitParts(data, options.heldout_fraction, options.max_fit_rows, d);
  ComputeScales(d);
  FallbackStates(data, sim, nominal_params, d);
  return d;
}

}  // namespace usvid::diagnosis
