// RefitVessel for one vessel type V (refit.h): the segment cost, the prior and the solve.
#pragma once

#include <ceres/ceres.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <string_view>

#include "core/error.h"
#include "methods/refit/refit.h"
#include "preprocessing/smoothing_spline.h"
#include "simulation/input_track.h"
#include "simulation/open_loop.h"
#include "simulation/recorded_inputs.h"
#include "simulation/segment_length.h"
#include "simulation/vessel_simulator.h"

namespace usvid::refit {

template <Vessel V>
constexpr int DynamicStates() {
  int n = 0;
  for (std::string_view s : V::kStateNames) n += IsPositionOrHeading(s) ? 0 : 1;
  return n;
}

template <Vessel V>
constexpr std::array<int, DynamicStates<V>()> DynamicIndices() {
  std::array<int, DynamicStates<V>()> idx{};
  int n = 0;
  for (int i = 0; i < V::kStates; ++i)
    if (!IsPositionOrHeading(V::kStateNames[i])) idx[n++] = i;
  return idx;
}

// One segment: rows [first, last] of the data simulated from the free dynamic states x0 (the
// kinematic ones from the data); residuals (simulated - measured) / sd of every dynamic state
// at every sampled row after the first.
template <Vessel V>
struct RefitSegment {
  static constexpr int C = DynamicStates<V>();
  const InputTrack* track;
  std::vector<double> times;
  Eigen::MatrixXd measured;  // rows x C
  Eigen::Matrix<bool, Eigen::Dynamic, Eigen::Dynamic> sampled;
  std::array<double, V::kStates> first;  // the data's first row (kinematic states used)
  std::array<double, C> sd;
  std::array<double, V::kParams> scale;
  double max_step;

  int Residuals() const { return static_cast<int>((times.size() - 1) * C); }

  template <typename T>
  bool operator()(const T* theta, const T* x0, T* res) const {
    constexpr int N = Plant<V>::kStates;
    constexpr auto dyn = DynamicIndices<V>();
    std::array<T, V::kParams> p;
    for (int i = 0; i < V::kParams; ++i) p[i] = theta[i] * scale[i];
    std::array<T, N> start;
    for (int i = 0; i < V::kStates; ++i) start[i] = T(first[i]);
    for (int c = 0; c < C; ++c) start[dyn[c]] = x0[c];
    const double* u0 = track->At(times[0]);  // the lag memory (unused: no effects here)
    for (int i = 0; i < V::kInputs; ++i) start[V::kStates + i] = T(u0[i]);
    OpenLoopSetup setup;
    setup.inputs = track;
    setup.times = times;
    setup.max_step = max_step;
    std::array<double, V::kInputs> limits;
    limits.fill(INFINITY);
    std::vector<T> out(times.size() * N);
    const size_t rows =
        RolloutOpenLoop<V, T>(setup, start.data(), p.data(), EffectValues<T>{}, limits, out.data());
    int k = 0;
    for (size_t row = 1; row < times.size(); ++row) {
      const size_t use = std::min(row, rows - 1);  // a diverged run keeps its last state
      for (int c = 0; c < C; ++c, ++k)
        res[k] =
            sampled(static_cast<Eigen::Index>(row), c)
                ? (out[use * N + dyn[c]] - T(measured(static_cast<Eigen::Index>(row), c))) / sd[c]
                : T(0);
    }
    return true;
  }
};

// The prior: (theta_i - 1) / prior_sd for the free parameters.
template <Vessel V>
struct RefitPrior {
  std::array<bool, V::kParams> free;
  double prior_sd;
  template <typename T>
  bool operator()(const T* theta, T* res) const {
    for (int i = 0; i < V::kParams; ++i) res[i] = free[i] ? (theta[i] - 1.0) / prior_sd : T(0);
    return true;
  }
};

template <Vessel V>
RefitResult RefitTyped(const VesselInfo& info, const Dataset& data,
                       const std::vector<double>& start, const RefitOptions& o) {
  constexpr int C = DynamicStates<V>();
  constexpr auto dyn = DynamicIndices<V>();
  RefitResult result;
  result.names = info.params;
  result.start = start;
  // Free parameters.
  std::array<bool, V::kParams> free{};
  std::vector<std::string> names = o.free;
  if (names.empty()) {
    if constexpr (requires { V::kRefitParams; }) {
      for (std::string_view n : V::kRefitParams) names.emplace_back(n);
    } else {
      for (int i = 0; i < V::kParams; ++i)
        if (V::kParamGroups[i] == ParamGroup::kDamping ||
            V::kParamGroups[i] == ParamGroup::kResistance)
          names.emplace_back(V::kParamNames[i]);
    }
  }
  for (const std::string& n : names) {
    const auto it = std::find(info.params.begin(), info.params.end(), n);
    if (it == info.params.end())
      throw InputError("--refit-params: vessel " + info.name + " has no parameter '" + n + "'");
    free[it - info.params.begin()] = true;
  }
  for (int i = 0; i < V::kParams; ++i)
    if (free[i]) result.free.push_back(info.params[i]);
  // Data: inputs, dynamic states, their measurement noise.
  const InputTrack track = RecordedInputs(data, info);
  std::array<const Channel*, C> channels;
  std::array<double, C> sd;
  for (int c = 0; c < C; ++c) {
    const std::string name(V::kStateNames[dyn[c]]);
    channels[c] = data.Find(name);
    if (channels[c] == nullptr)
      throw InputError(data.SourcePrefix() + "refit of " + info.name + " needs state column '" +
                       name + "'");
    result.channels.push_back(name);
    // Residuals in units of the measurement noise (its sd estimated from the samples, at least
    // 0.1 % of the channel's spread: noise-free and quantised data), so that the data term is a
    // chi-square and the prior's relative sd means what it says.
    std::vector<double> samples;
    for (Eigen::Index k = 0; k < data.rows(); ++k)
      if (channels[c]->sampled(k)) samples.push_back(channels[c]->values(k));
    const Eigen::Map<const Eigen::VectorXd> y(samples.data(),
                                              static_cast<Eigen::Index>(samples.size()));
    const double spread = y.size() > 1 ? std::sqrt((y.array() - y.mean()).square().mean()) : 1.0;
    const double noise = y.size() >= 16 ? EstimateNoiseSd(y) : 0.0;
    sd[c] = std::max({noise, 1e-3 * spread, 1e-12});
  }
  if (!(o.segment_s >= 0)) throw InputError("refit: --segment must be positive (0: automatic)");
  const double segment_s = o.segment_s > 0 ? o.segment_s : AutomaticSegmentSeconds(data, info);
  result.segment_s = segment_s;
  if (!(o.prior_sd > 0)) throw InputError("refit: the prior's standard deviation must be positive");
  std::array<double, V::kParams> scale, theta;
  for (int i = 0; i < V::kParams; ++i) {
    scale[i] = start[i] != 0.0 ? std::abs(start[i]) : 1.0;
    theta[i] = start[i] / scale[i];
  }
  const double dt = data.rows() > 1 ? data.duration() / static_cast<double>(data.rows() - 1) : 1.0;
  // Segments of segment_s seconds (the last may be shorter; at least two rows each).
  std::vector<std::pair<Eigen::Index, Eigen::Index>> bounds;
  for (Eigen::Index a = 0; a + 1 < data.rows();) {
    Eigen::Index b = a + 1;
    while (b + 1 < data.rows() && data.t()(b + 1) - data.t()(a) <= segment_s) ++b;
    bounds.emplace_back(a, b);
    a = b;
  }
  if (bounds.empty()) throw InputError(data.SourcePrefix() + "refit needs at least two rows");
  std::vector<std::array<double, C>> x0(bounds.size());
  ceres::Problem problem;
  for (size_t j = 0; j < bounds.size(); ++j) {
    const auto [a, b] = bounds[j];
    auto* seg = new RefitSegment<V>;
    seg->track = &track;
    seg->max_step = std::min(dt, 0.5) * 1.0000001;
    for (Eigen::Index k = a; k <= b; ++k) seg->times.push_back(data.t()(k));
    seg->measured.resize(b - a + 1, C);
    seg->sampled.resize(b - a + 1, C);
    for (Eigen::Index k = a; k <= b; ++k)
      for (int c = 0; c < C; ++c) {
        seg->sampled(k - a, c) = channels[c]->sampled(k);
        seg->measured(k - a, c) = channels[c]->sampled(k) ? channels[c]->values(k) : 0.0;
      }
    for (int i = 0; i < V::kStates; ++i) {
      const Channel* ch = data.Find(std::string(V::kStateNames[i]));
      seg->first[i] = ch != nullptr && ch->sampled(a) ? ch->values(a) : 0.0;
    }
    for (int c = 0; c < C; ++c) x0[j][c] = seg->first[dyn[c]];
    seg->sd = sd;
    seg->scale = scale;
    const int residuals = seg->Residuals();
    problem.AddResidualBlock(
        new ceres::AutoDiffCostFunction<RefitSegment<V>, ceres::DYNAMIC, V::kParams, C>(seg,
                                                                                        residuals),
        nullptr, theta.data(), x0[j].data());
  }
  problem.AddResidualBlock(new ceres::AutoDiffCostFunction<RefitPrior<V>, V::kParams, V::kParams>(
                               new RefitPrior<V>{free, o.prior_sd}),
                           nullptr, theta.data());
  std::vector<int> held;
  for (int i = 0; i < V::kParams; ++i)
    if (!free[i]) held.push_back(i);
  if (held.size() == static_cast<size_t>(V::kParams))
    problem.SetParameterBlockConstant(theta.data());
  else if (!held.empty())
    problem.SetManifold(theta.data(), new ceres::SubsetManifold(V::kParams, held));

  ceres::Solver::Options so;
  so.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  so.max_num_iterations = o.max_iterations;
  so.num_threads = std::max(1, o.threads);
  so.function_tolerance = 1e-10;
  ceres::Solver::Summary summary;
  const auto t0 = std::chrono::steady_clock::now();
  ceres::Solve(so, &problem, &summary);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  result.termination = ceres::TerminationTypeToString(summary.termination_type) +
                       std::string(": ") + summary.message;
  result.converged = summary.termination_type == ceres::CONVERGENCE;
  result.initial_cost = summary.initial_cost;
  result.final_cost = summary.final_cost;
  result.iterations = static_cast<int>(summary.iterations.size());
  result.segments = static_cast<int>(bounds.size());
  result.params.resize(V::kParams);
  result.sd.assign(V::kParams, 0.0);
  for (int i = 0; i < V::kParams; ++i) result.params[i] = theta[i] * scale[i];
  return result;
}

}  // namespace usvid::refit
