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
#include <string>

#include "core/dataset.h"
#include "metrics/free_run.h"

namespace usvid {

struct Evaluation {
  nlohmann::json metrics;  // the metrics.json object
  FreeRun run;
};

inline constexpr double kHorizonsS[] = {5.0, 30.0};
inline constexpr double kValidPredictionError = 0.5;

Evaluation EvaluateModel(const nlohmann::json& model, const Dataset& data);

// Each channel's fit % of the model restarted from the measured state every `horizon_s`.
std::map<std::string, double> HorizonFit(const nlohmann::json& model, const Dataset& data,
                                         double horizon_s);
// The key of a horizon in "horizon_fit_percent": "5", "30" (whole seconds), or "all".
std::string HorizonKey(double horizon_s);

}  // namespace usvid
