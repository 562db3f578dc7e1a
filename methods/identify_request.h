// What `usvid identify`, a suite's method and the design's checks ask of a method: which method,
// on which channels (a vessel's, or named), the preprocessing, the seed and threads, which every
// method shares, and the method's own options (methods/method_options.h), as given: Identify
// checks them against the method's declaration before it fits.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "preprocessing/pipeline.h"
#include "simulation/vessel_ref.h"

namespace usvid {

// The most rows a Ceres fit of fossen-ceres, refit or hybrid uses unless its fit_rows says: 20
// minutes at 50 Hz. Ceres holds the Jacobian of every residual twice over (its block-sparse
// matrix and a copy with the Levenberg-Marquardt rows appended), about 600 bytes a row for the
// shooting fits, so a 10-hour log would take gigabytes; 60000 rows are far more than the ten or
// so parameters need, and shorter records are fitted whole.
inline constexpr long kCeresFitRows = 60000;

struct IdentifyRequest {
  std::string method;  // a registered method's name (methods/registry.h)
  VesselRef vessel;    // states and inputs from it (when not given); resolved where named
  std::vector<std::string> states, inputs;
  std::string data_name;  // for model.json's train.data
  PreprocessOptions preprocess;
  uint64_t seed = 1;
  int threads = 0;
  // The vessel's parameters a vessel model starts from (nominal, refit, hybrid: --params);
  // empty: the vessel's defaults.
  std::vector<double> start_params;
  // The method's options, key -> value (an object; null: none), as its declaration names them.
  nlohmann::json options;
};

}  // namespace usvid
