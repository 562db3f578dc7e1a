// `fossen-ceres`: the parametric Fossen 3-DOF model of odin3dof (docs/model.md#odin3dof: M, C(nu)
// from M, D(nu) with linear and quadratic terms; 10 parameters m11 m22 m33 Xu Xuu Yv Yvv Nv Nr
// Nrr), and the same model driven through a waterjet input map (13 parameters, inputs throttle,
// nozzle, bucket; see fossen_models.h) or a rudder-propeller map (inputs delta, rev); and the
// high-speed form on the jets' measured forces with speed-dependent damping (jet_force_model.h).
// Fitted with Ceres in two modes:
//  - equation error: on estimated derivatives, residual_k = (M nu' + C(nu) nu + D(nu) nu - tau)_k
//    per sample, each force or moment divided by its input's standard deviation; for the
//    waterjet model (tau not measured) in accelerations, nu'_k - (M^-1 (tau - C nu - D nu))_k,
//    each divided by the standard deviation of nu'_k;
//  - simulation error by multiple shooting: the data cut into segments of segment_s seconds;
//    each segment is simulated by the templated plant (RK4, one step per sample) from its own
//    free initial velocities, residuals are the simulated minus measured u, v, r (divided by
//    their standard deviations), and segments are tied by continuity residuals (end of one minus
//    start of the next, weighted). Ceres differentiates whole rollouts with Jets.
// On a record longer than max_rows, both fit a share of it spread evenly over the whole: the
// equation error every k-th batch of consecutive samples, the shooting every k-th segment (a
// segment whose successor is left out has no continuity residual).
// Parameters are bounded below (positive, but for those a model says are signed), a Huber loss is
// optional, and their standard deviations come from (J^T J)^-1 s^2 at the solution. The
// simulation-error fit starts from the equation-error one.
#pragma once

#include <string_view>

#include <array>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/dataset.h"
#include "preprocessing/pipeline.h"

namespace usvid::fossen {

// The name --method and suites give it (methods/method_list.h registers it).
inline constexpr std::string_view kMethodName = "fossen-ceres";

enum class FitMode { kEquationError, kSimulationError };

struct FossenOptions {
  FitMode mode = FitMode::kSimulationError;
  double segment_s = 10.0;
  double continuity_weight = 10.0;
  bool robust = false;  // Huber loss (scale 1 in normalised units)
  int max_iterations = 100;
  // Ceres stops when a step changes the cost by less than this share of it. The shooting fits
  // converge linearly in their last steps (odin-hs's waterjet map on 600 s of random steps: each
  // step's change 0.61 times the last), so 1e-8 stops 15 steps before 1e-12 did (47 of 62) with
  // the cost the same to about 1e-8 (docs/performance.md#the-default-compare-issue-36).
  double function_tolerance = 1e-8;
  int threads = 1;
  // Most rows the fits use (0: all). On a longer record the equation error's batches and the
  // shooting segments are spread evenly over it: Ceres holds the Jacobian of every residual, and
  // a 2-hour 50 Hz log's took 400 MB. Records of this length or shorter are fitted whole.
  long max_rows = 0;
  // The equation-error fit's starting values, one per model parameter; empty: the model's
  // kStart. A vessel file's ship starts from KVLCC2's, Froude-scaled to its length
  // (RudderRpsModel, fossen_models.h). The held parameter (kFixedParam) stays at its start.
  std::vector<double> start;
};

template <int N>
struct BasicFossenFit {
  std::array<double, N> params{};
  std::array<double, N> sd{};  // (J^T J)^-1 s^2 (0 where not available)
  bool covariance_ok = false;
  std::string termination;  // Ceres' termination type and message
  bool converged = false;
  double initial_cost = 0.0, final_cost = 0.0;
  int iterations = 0;
  long rows = 0;  // the samples fitted (all, or a share of a record longer than max_rows)
  double seconds = 0.0;
};
using FossenFit = BasicFossenFit<10>;  // odin3dof: m11 .. Nrr

// The fits, for each model of fossen_models.h and jet_force_model.h (Odin3DofModel,
// WaterjetModel, RudderModel, JetForceModel). prepared: from Preprocess with states u, v, r
// (smoothed, "_dot" derivatives) and the model's inputs (Model::kInputNames); raw states
// "<s>_raw" are what the simulation error compares against. A model whose scale is not fixed by
// measured forces (waterjet, rudder) holds m11 at its start (5000 kg in the equation-error fit,
// start[0] in the simulation-error one): scaling all its parameters together leaves it unchanged.
template <typename Model>
BasicFossenFit<Model::kParams> FitEquationErrorFor(const PreparedData& prepared,
                                                   const FossenOptions& options);
template <typename Model>
BasicFossenFit<Model::kParams> FitSimulationErrorFor(
    const PreparedData& prepared, const std::array<double, Model::kParams>& start,
    const FossenOptions& options);
// The model written out as equations in channel names (docs/data.md#modeljson).
template <typename Model>
nlohmann::json EquationsFor(const std::array<double, Model::kParams>& params);

}  // namespace usvid::fossen
