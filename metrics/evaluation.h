// Scores a model on data it may never have seen (contract section 5, metrics.json): the model's
// free run on the data's inputs, per channel fit %, NRMSE and RMSE; the one-step derivative R^2
// of each equation against derivatives estimated from the data; whether the free run diverged;
// and the position drift at the end where positions are measured.
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
