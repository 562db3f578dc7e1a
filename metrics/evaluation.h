// Scores a model on data it may never have seen (contract section 5, metrics.json): the model's
// free run on the data's inputs, per channel fit %, NRMSE and RMSE; k-step-ahead NRMSE (k = 10
// and 40 samples: the model run k steps from every k-th measured state); the one-step derivative
// R^2 of each equation against derivatives estimated from the data; whether the free run diverged;
// and the position drift at the end where positions are measured. With a speed channel (U, or
// u and v) and a hull length (model "length_m", else its vessel's, else 10.5 m: Odin), the
// channel scores are also given per speed regime by Froude number U / sqrt(g L): displacement
// (< 0.4), semi-displacement (0.4 to 1.1) and planing (> 1.1), over the rows measured in each.
#pragma once

#include <nlohmann/json.hpp>

#include "core/dataset.h"
#include "metrics/free_run.h"

namespace usvid {

struct Evaluation {
  nlohmann::json metrics;  // the metrics.json object
  FreeRun run;
};

Evaluation EvaluateModel(const nlohmann::json& model, const Dataset& data);

}  // namespace usvid
