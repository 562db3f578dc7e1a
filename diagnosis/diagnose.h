// `usvid diagnose`: what a nominal simulation gets wrong on measured data, which effect of the
// catalogue causes it, the model extended by that effect, and the gain on held-out data.
//  1. Show: the nominal simulator on the measured inputs, free run and segment-reset
//     (measured_data.h); per channel fit, bias, drift, lag and residual correlations
//     (residual_analysis.h).
//  2. Name: every effect fitted on the training part (effect_fitter.h) and scored on the
//     held-out part. E = mean squared normalised residual; the score is Akaike's criterion
//     relative to the nominal model, N ln(E / E_nominal) + 2 k (N held-out residuals, k sizes);
//     candidates ranked by score. The best is the cause when it removes a real part of the
//     error the noise does not explain:
//       excess    = E_nominal / E_floor - 1 >= min_excess  (E_floor: measurement noise alone),
//       explained = (E_nominal - E_best) / (E_nominal - E_floor) >= min_explained;
//     otherwise the cause is "none".
//  3. Extend and measure: the nominal model with the cause's fitted sizes; held-out fit before
//     and after; gain = 1 - ||e_extended|| / ||e_nominal|| on the held-out part.
//  4. Beyond the catalogue: when the residual stays well above the noise and no effect explains
//     it, a sparse regression (SINDy) on the derivative residual proposes the missing terms.
#pragma once

#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "core/dataset.h"
#include "diagnosis/effect_fitter.h"
#include "diagnosis/residual_analysis.h"

namespace usvid::diagnosis {

struct DiagnoseOptions {
  SplitOptions split;
  double min_excess = 0.1;
  double min_explained = 0.5;
  bool discover = true;  // step 4
};

using FitPercent = std::map<std::string, double>;

struct Candidate {
  EffectFit fit;
  FitPercent heldout_fit_percent;
  double heldout_error = 0.0;  // E on the held-out part
  double explained = 0.0;      // of the excess error over the noise floor
  double score = 0.0;
  double seconds = 0.0;
};

// A term proposed for a state's derivative by the sparse regression on the residual.
struct DiscoveredTerms {
  std::string state;
  std::string expression;   // the missing part of d(state)/dt, in channel names
  double heldout_r2 = 0.0;  // of the derivative residual on the held-out part
};

// What a person looks at: measured, nominal and extended channels on the held-out part.
struct HeldoutSeries {
  Eigen::VectorXd t;
  std::map<std::string, Eigen::VectorXd> measured, nominal, extended;
};

struct Diagnosis {
  std::string vessel;
  std::string source;
  std::vector<std::string> param_names;
  std::vector<double> params;
  std::vector<std::string> channels;
  double train_s = 0.0, heldout_s = 0.0, segment_s = 0.0;

  FitPercent nominal_fit_percent;  // held-out, segment-reset
  FitPercent nominal_free_run_fit_percent;
  double nominal_error = 0.0, noise_floor = 0.0;
  std::vector<ChannelResidual> residuals;

  std::vector<Candidate> candidates;  // ranked, best first
  std::string cause = "none";
  std::optional<Effect> cause_effect;
  FitPercent extended_fit_percent;
  double extended_error = 0.0;
  double heldout_error_reduction = 0.0;
  std::vector<DiscoveredTerms> discovered;
  HeldoutSeries series;
  double seconds = 0.0;
};

Diagnosis Diagnose(const Dataset& data, const std::string& vessel, const std::vector<double>& params,
                   const DiagnoseOptions& options, std::ostream* log = nullptr);

}  // namespace usvid::diagnosis
