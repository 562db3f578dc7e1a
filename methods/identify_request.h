// What `usvid identify`, a suite's method and the design's checks ask of a method: which method,
// on which channels (a vessel's, or named), the preprocessing, and the methods' own options.
// Each method reads the options it takes (methods/method.h) and validates them.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "preprocessing/pipeline.h"

namespace usvid {

// The most rows a Ceres fit of fossen-ceres, refit or hybrid uses unless --fit-rows says: 20
// minutes at 50 Hz. Ceres holds the Jacobian of every residual twice over (its block-sparse
// matrix and a copy with the Levenberg-Marquardt rows appended), about 600 bytes a row for the
// shooting fits, so a 10-hour log would take gigabytes; 60000 rows are far more than the ten or
// so parameters need, and shorter records are fitted whole.
inline constexpr long kCeresFitRows = 60000;

struct IdentifyRequest {
  std::string method;  // a registered method's name (methods/registry.h)
  std::string vessel;  // states and inputs from it (when not given)
  std::vector<std::string> states, inputs;
  std::string data_name;  // for model.json's train.data
  PreprocessOptions preprocess;
  // gp: an unset option takes its value from the preset: "default" (gp::GpOptions, terms
  // chosen by held-out error, model chosen by short-horizon simulation) or "report" (the
  // reference report's Table 3.1, gp::ReportOptions, no validation part).
  std::string preset = "default";
  std::string operators = "+,-,*";
  std::optional<int> population, generations, max_depth, restarts, constant_iterations;
  std::optional<double> ols_threshold, validation_fraction;
  // gp: the short-horizon simulations' length [s] (model selection and the simulation refit);
  // unset: 10 s, or kRegimeHorizonS on a record with regime features.
  std::optional<double> horizon_s;
  std::string fitness = "r2";
  // Regime features for gp and sindy (regime_features.h): auto, hinges, froude or none.
  std::string features = "auto";
  // gp: the rows the search scores on (GpOptions::fit_rows); fossen-ceres, refit and hybrid: the
  // most rows their Ceres fits use, spread over a longer record (kCeresFitRows); 0: all.
  std::optional<long> fit_rows;
  uint64_t seed = 1;
  int threads = 0;
  // fossen-ceres: "simulation" (multiple shooting) or "equation" error; gp: how the chosen
  // terms' weights are fitted, by "equation" error or by it and then by "simulation" error.
  std::string fit_mode = "simulation";
  double segment_s =
      0.0;  // shooting segment [s]; 0: the method's default (fossen 10 s, refit auto)
  bool robust = false;
  // refit (methods/refit/refit.h); also segment_s
  std::vector<std::string> refit_params;
  double prior_sd = 0.5;
  std::vector<double> start_params;  // empty: the vessel's defaults
  // hybrid (methods/hybrid/hybrid.h); also the refit options above
  std::optional<int> hybrid_terms;
};

}  // namespace usvid
