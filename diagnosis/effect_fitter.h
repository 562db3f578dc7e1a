// Fits one effect of the catalogue to a part of measured data through a vessel's simulator, and
// computes the residuals of the nominal or an extended model (reset_rollout.h). A runtime
// interface so that the diagnosis picks the vessel by name; the typed implementation is
// typed_effect_fitter.h, instantiated once per vessel type in a translation unit of its own
// (effect_fitter_vessel.cc.in), and effect_fitter_registry.cc holds one of each.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "diagnosis/effect_search.h"
#include "diagnosis/measured_data.h"
#include "simulators/vessel.h"

namespace usvid::diagnosis {

struct EffectFit {
  Effect effect;
  double train_cost = 0.0;  // mean squared normalised residual on the training part
  std::vector<double> sd;   // standard deviation of each size (Ceres covariance), empty if none
  int evaluations = 0;      // rollouts (NLopt) or solver iterations (Ceres)
  std::string message;      // how the optimiser ended
};

class EffectFitter {
 public:
  virtual ~EffectFitter() = default;
  // Residuals of `part` (ResidualCount values, row-major rows x channels) of the nominal model
  // (no effect) or with one effect, each segment's initial state estimated (segment_cost.h).
  virtual Eigen::VectorXd Residuals(const MeasuredData& data, const Part& part,
                                    const std::vector<double>& params,
                                    const std::optional<Effect>& effect) const = 0;
  // Residuals of the plain reset run (reset_rollout.h: each segment from the smoothed
  // measurement), what a person compares by eye.
  virtual Eigen::VectorXd ResetResiduals(const MeasuredData& data, const Part& part,
                                         const std::vector<double>& params,
                                         const EffectValues<double>& effects) const = 0;
  virtual EffectFit Fit(const MeasuredData& data, const Part& train,
                        const std::vector<double>& params, const EffectSearch& search) const = 0;
  virtual int YawInput() const = 0;
  virtual std::string_view Name() const = 0;
  // The nominal vessel derivative dx = f(x, u; params), no effects.
  virtual void Derivative(const std::vector<double>& params, const double* x, const double* u,
                          double* dx) const = 0;
};

// A new fitter for vessel type V (typed_effect_fitter.h defines it).
template <Vessel V>
std::unique_ptr<const EffectFitter> NewEffectFitter();

// Throws InputError for a vessel without a fitter.
const EffectFitter& FindEffectFitter(const std::string& vessel);

}  // namespace usvid::diagnosis
