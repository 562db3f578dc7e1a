// Measured data as the diagnosis sees them: the recorded commands as a zero-order-hold input
// track, the measured vessel states (the scored channels) with their sampled masks, and the
// data cut into a training part and a held-out part, each into segments of about segment_s
// seconds. Every segment is simulated from its own initial state (the smoothed measurement in
// the reset run, an estimated one when scoring; reset_rollout.h, segment_cost.h), so an unstable
// hull or a wrong initial heading cannot swamp the comparison, while effects that act over
// seconds to minutes still show. Unmeasured states and the actuators' memory run on.
// Each channel's error is divided by its scale: the RMS change of that channel within a segment,
// so that positions, angles and rates weigh alike.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/dataset.h"
#include "simulation/input_track.h"
#include "simulation/vessel_simulator.h"

namespace usvid::diagnosis {

struct Part {
  Eigen::Index begin = 0, end = 0;   // rows [begin, end)
  std::vector<Eigen::Index> starts;  // first row of each segment, ascending, starts[0] == begin
};

// The first and one-past-last row of segment s of a part.
inline std::pair<Eigen::Index, Eigen::Index> SegmentRows(const Part& part, size_t s) {
  return {part.starts[s], s + 1 < part.starts.size() ? part.starts[s + 1] : part.end};
}

struct MeasuredData {
  std::string vessel;
  std::vector<double> times;
  // The commands; a logged wind as the air over the ground where the record logs psi, u and v
  // (base.wind_over_ground: each segment meets it on its own heading).
  InputTrack inputs{0};
  std::vector<double> peak_command;  // max |command| per input over the whole data
  std::vector<bool> measured_input;  // per input: a measured disturbance (wind), not a command
  // The record has wind and the vessel feels it (VesselInfo::wind_body): the effect wind is a
  // candidate.
  bool wind = false;

  std::vector<std::string> channels;  // scored: vessel states in the data that vary
  std::vector<int> channel_state;     // channel -> vessel state index
  std::vector<int> state_channel;     // vessel state -> channel (-1: not measured)
  Eigen::MatrixXd measured;           // rows x channels (0 where not sampled)
  Eigen::Array<bool, Eigen::Dynamic, Eigen::Dynamic> sampled;  // rows x channels
  // Where a segment starts its states are set from a smoothing spline of each channel (auto
  // lambda, preprocessing/smoothing_spline.h), not from the noisy sample: on an unstable hull
  // the noise of one sample would otherwise set the whole segment's course.
  Eigen::MatrixXd reset;         // rows x channels (0 where not sampled)
  std::vector<double> noise_sd;  // per channel, estimated by the smoother
  std::vector<double> scale;     // per channel
  int rate_channel = -1;         // the gyro's channel (sensor_bias), -1 if absent
  int heading_channel = -1;      // an angle: errors wrapped to (-pi, pi]
  // A nominal free run of every vessel state over all rows: where a segment starts, states the
  // data do not measure (jet rpm, nozzle angle) start from it.
  Eigen::MatrixXd fallback_states;  // rows x vessel states

  Part train, heldout, all;
  // The rows the candidate effects are fitted on: the training part, or on a long record its
  // last SplitOptions::max_fit_rows rows (whole segments), so that the fits' Jacobians and time
  // stay bounded however long the log. The held-out part is bounded alike: on a long record it
  // is the first max_fit_rows rows after the training part.
  Part fit;
  double max_step = 0.05;   // integration substep [s]
  double segment_s = 10.0;  // the segment length used (SplitOptions::segment_s, or automatic)
  // Effects the nominal model already has (a diagnosis of a model diagnosed before, or the
  // causes named in earlier rounds); every rollout starts from them.
  EffectValues<double> base;

  Eigen::Index rows() const { return static_cast<Eigen::Index>(times.size()); }
};

struct SplitOptions {
  // Segment length [s]; 0: automatic, 1.5 hull lengths of travel at the median speed and at least
  // 10 s (a 320 m tanker at 8 m/s: 60 s; small craft: 10 s).
  double segment_s = 0.0;
  double heldout_fraction = 1.0 / 3.0;  // the last part of the record
  double max_step = 0.0;  // integration substep [s]; 0: the data's interval, at most 0.05 s
  // Most rows the candidates are fitted on, the training part's last, and scored on, the
  // held-out part's first (0: the whole parts). 60000 rows are 20 minutes at 50 Hz, as for the
  // Ceres fits of identify (methods/identify_request.h): a 2-hour log's fits then take 180 MB,
  // not 400 MB, and its diagnosis under a minute on 2 cores, not 80 s.
  Eigen::Index max_fit_rows = 60000;
};

// Throws InputError (naming the file from the data's "source" metadata) when an input column
// is missing, no state channel of the vessel is measured, or the record is too short to split.
MeasuredData PrepareMeasuredData(const Dataset& data, const VesselSimulator& sim,
                                 const std::vector<double>& nominal_params,
                                 const SplitOptions& options);

}  // namespace usvid::diagnosis
