#include "methods/gp/simulation_refit.h"

#include <ceres/ceres.h>

#include <algorithm>
#include <cmath>

#include "core/dataset.h"
#include "core/evenly_spread.h"

namespace usvid::gp {
namespace {

// `models` with the biases and weights of `parameters` (one block per model: bias, then weights).
std::vector<Model> WithParameters(const std::vector<Model>& models,
                                  const std::vector<const double*>& parameters) {
  std::vector<Model> out = models;
  for (size_t s = 0; s < out.size(); ++s) {
    out[s].bias = parameters[s][0];
    for (size_t t = 0; t < out[s].weights.size(); ++t) out[s].weights[t] = parameters[s][t + 1];
  }
  return out;
}

// The error of `models` on segments of `steps` from each of `starts`; `residuals` as
// SegmentSimulator::Error gives them.
double Error(const SegmentSimulator& sim, const std::vector<Model>& models,
             const std::vector<long>& starts, long steps, bool& diverged,
             std::vector<double>* residuals = nullptr) {
  std::vector<const Model*> pointers;
  for (const Model& m : models) pointers.push_back(&m);
  return sim.Error(pointers, starts, steps, diverged, nullptr, residuals);
}

// The free run of the whole record (each stretch between gaps from its start).
double FreeRunError(const SegmentSimulator& sim, const std::vector<Model>& models, bool& diverged) {
  std::vector<const Model*> pointers;
  for (const Model& m : models) pointers.push_back(&m);
  return sim.FreeRunError(pointers, diverged);
}

// Residuals of every segment for the models with the parameter blocks' biases and weights;
// false when a segment leaves the bounds.
class SegmentResiduals {
 public:
  SegmentResiduals(const SegmentSimulator& sim, const std::vector<Model>& models,
                   const std::vector<long>& starts, long steps)
      : sim_(sim), models_(models), starts_(starts), steps_(steps) {}

  bool operator()(double const* const* parameters, double* residuals) const {
    const std::vector<const double*> blocks(parameters, parameters + models_.size());
    bool diverged = false;
    std::vector<double> r;
    Error(sim_, WithParameters(models_, blocks), starts_, steps_, diverged, &r);
    if (diverged) return false;
    std::copy(r.begin(), r.end(), residuals);
    return std::all_of(r.begin(), r.end(), [](double x) { return std::isfinite(x); });
  }

 private:
  const SegmentSimulator& sim_;
  const std::vector<Model>& models_;
  const std::vector<long>& starts_;
  long steps_;
};

}  // namespace

SimulationRefit RefitBySimulation(const SelectionData& data, const std::vector<int>& state_vars,
                                  std::vector<Model>& models,
                                  const SimulationRefitOptions& options) {
  SimulationRefit out;
  const long rows = data.t.size();
  if (rows < 3 || models.empty() || models.size() != state_vars.size()) {
    out.reason = "too few rows or no equations";
    return out;
  }
  const double dt = MedianInterval(data.t);
  const long steps = std::clamp<long>(std::lround(options.horizon_s / dt), 1, rows - 1);
  const long fit_rows = std::clamp<long>(options.fit_rows, 0, rows);
  const std::vector<long> all = SegmentSimulator::Starts(data.t, 0, fit_rows, steps);
  std::vector<long> starts;
  for (const long i :
       EvenlySpread(static_cast<long>(all.size()), std::max<long>(1, options.max_rows / steps)))
    starts.push_back(all[static_cast<size_t>(i)]);
  const std::vector<long> check = SegmentSimulator::Starts(data.t, fit_rows, rows, steps);
  out.segments = static_cast<int>(starts.size());
  out.validation_segments = static_cast<int>(check.size());
  if (starts.empty() || check.empty()) {
    out.reason = "the fit part or the rest is shorter than a segment";
    return out;
  }
  const SegmentSimulator sim(data, state_vars);

  bool diverged = false;
  out.free_run_error_before = FreeRunError(sim, models, diverged);
  out.validation_error_before = Error(sim, models, check, steps, diverged);

  std::vector<std::vector<double>> p;
  for (const Model& m : models) {
    p.push_back({m.bias});
    p.back().insert(p.back().end(), m.weights.begin(), m.weights.end());
    out.parameters += static_cast<int>(p.back().size());
  }
  auto* cost = new ceres::DynamicNumericDiffCostFunction<SegmentResiduals, ceres::CENTRAL>(
      new SegmentResiduals(sim, models, starts, steps));
  for (const std::vector<double>& block : p)
    cost->AddParameterBlock(static_cast<int>(block.size()));
  cost->SetNumResiduals(static_cast<int>(starts.size() * steps * state_vars.size()));
  ceres::Problem problem;
  std::vector<double*> blocks;
  for (std::vector<double>& block : p) blocks.push_back(block.data());
  problem.AddResidualBlock(cost, nullptr, blocks);
  ceres::Solver::Options solver;
  solver.linear_solver_type = ceres::DENSE_QR;
  solver.max_num_iterations = options.max_iterations;
  solver.num_threads = 1;
  solver.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(solver, &problem, &summary);
  out.iterations = static_cast<int>(summary.iterations.size());
  // Ceres's cost is half the sum of squares; the error is their mean.
  const double n = static_cast<double>(cost->num_residuals());
  out.initial_error = 2.0 * summary.initial_cost / n;
  out.final_error = 2.0 * summary.final_cost / n;
  if (summary.termination_type == ceres::FAILURE || !std::isfinite(summary.final_cost) ||
      !(summary.final_cost < summary.initial_cost)) {
    out.reason = "the refit did not lower the simulation error (" + summary.message + ")";
    return out;
  }
  std::vector<Model> refitted = WithParameters(models, {blocks.begin(), blocks.end()});
  out.validation_error_after = Error(sim, refitted, check, steps, diverged);
  if (diverged || !(out.validation_error_after < out.validation_error_before)) {
    out.reason = "the refitted weights did not lower the simulation error of the validation part";
    return out;
  }
  out.free_run_error_after = FreeRunError(sim, refitted, diverged);
  if (diverged) {
    out.reason = "the refitted model left the bounds in a free run of the record";
    return out;
  }
  models = std::move(refitted);
  out.accepted = true;
  out.reason =
      "lowered the simulation error of the fit part and of the validation part, and free-runs "
      "the record within the bounds";
  return out;
}

}  // namespace usvid::gp
