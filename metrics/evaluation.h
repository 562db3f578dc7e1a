// Scores a model on data it may never have seen (docs/data.md#metricsjson): the model's
// free run on the data's inputs, per channel fit %, NRMSE and RMSE; k-step-ahead NRMSE (k = 10
// and 40 samples: the model run k steps from every k-th measured state); the one-step derivative
// R^2 of each equation against derivatives estimated from the data; whether the free run diverged;
// and the position drift at the end where positions are measured. With a speed channel (U, or
// u and v) and a hull length (model "length_m", else its vessel's, else 10.5 m: Odin), the
// channel scores are also given per speed regime by Froude number U / sqrt(g L): displacement
// (< 0.4), semi-displacement (0.4 to 1.1) and planing (> 1.1), over the rows measured in each.
//
// Prediction horizons ("horizon_fit_percent"): the model restarted from the measured state every
// H seconds (H = 5 and 30; "all" is the free run), each channel's fit % over the whole record
// of those predictions. Short-term quality is so measured apart from long-horizon instability,
// which an open-loop free run of a directionally unstable hull turns equation errors of a
// fraction of a percent into. "valid_prediction_s": how long the free run stays within
// kValidPredictionError of the record, by the RMS over the dynamic channels (not positions or
// heading) of each error in units of that channel's standard deviation.
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "core/dataset.h"
#include "metrics/fit_metrics.h"
#include "metrics/free_run.h"

namespace usvid {

// A model's scores on one record, typed: what the harness copies into its rows, and what
// ToJson writes as metrics.json. A new metric is a field here, filled by EvaluateModel, and its
// line in ToJson (and in harness/result_row.h when a suite's tables show it).
struct Scores {
  std::map<std::string, ChannelScore> channels;  // the free run's, per channel
  // One-step derivative R^2 per equation (NaN where it is not defined); empty for a vessel
  // model or data that lack a variable of the equations.
  std::map<std::string, double> derivative_r2;
  bool diverged = false;
  double diverged_at_s = 0.0;  // when diverged
  std::string diverged_channel;
  long samples = 0;
  double seconds = 0.0;
  // k ("10", "40") -> channel -> NRMSE k samples after every k-th measured state.
  std::map<std::string, std::map<std::string, double>> k_step_nrmse;
  // Horizon (HorizonKey: "5", "30", "all") -> channel -> fit %.
  std::map<std::string, std::map<std::string, double>> horizon_fit_percent;
  std::optional<double> valid_prediction_s;
  struct Regime {
    long samples = 0;
    std::map<std::string, ChannelScore> channels;
  };
  // By speed regime ("displacement", "semi-displacement", "planing"), when the data give a
  // speed; regimes with fewer than 10 rows are left out.
  std::optional<std::map<std::string, Regime>> regimes;
  std::optional<double> position_drift_m;  // when positions are measured and simulated

  nlohmann::json ToJson() const;  // the metrics.json object (docs/data.md#metricsjson)
};

struct Evaluation {
  Scores scores;
  nlohmann::json metrics;  // scores.ToJson(); null for EvaluationScope::kFreeRunOnly
  FreeRun run;
};

inline constexpr double kHorizonsS[] = {5.0, 30.0};
inline constexpr double kValidPredictionError = 0.5;

// How much EvaluateModel computes: every score (metrics.json); all but the k-step NRMSE, which a
// suite's rows do not read and which costs about two free runs; or the free run alone (a plot).
enum class EvaluationScope { kAll, kRowScores, kFreeRunOnly };

Evaluation EvaluateModel(const nlohmann::json& model, const Dataset& data,
                         EvaluationScope scope = EvaluationScope::kAll);

// Each channel's fit % of the model restarted from the measured state every `horizon_s`.
std::map<std::string, double> HorizonFit(const nlohmann::json& model, const Dataset& data,
                                         double horizon_s);
// The key of a horizon in "horizon_fit_percent": "5", "30" (whole seconds), or "all".
std::string HorizonKey(double horizon_s);

}  // namespace usvid
