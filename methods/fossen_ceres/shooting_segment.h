// One segment of fossen-ceres's multiple-shooting fit (typed_fossen_fit.h): the residuals of a
// model simulated over the segment's rows from its free initial velocities, as a Ceres functor
// on any scalar (doubles, or Jets for the fit's derivatives: ceres::AutoDiffCostFunction or
// knot_window_cost.h).
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "simulation/input_track.h"
#include "simulation/open_loop.h"

namespace usvid::fossen {

// p = theta * scale, in the functors' scalar type.
template <int N, typename T>
std::array<T, N> Unscale(const T* theta, const std::array<double, N>& scale) {
  std::array<T, N> p;
  for (int i = 0; i < N; ++i) p[i] = theta[i] * scale[i];
  return p;
}

// One shooting segment: rows [begin, end] simulated from the free initial velocities x0; the
// residuals are the normalised errors of u, v, r at every row after the first, then the
// weighted continuity error between the simulated end and the next segment's start.
template <typename Model>
struct SegmentResidual {
  const InputTrack* track;
  std::vector<double> times;
  Eigen::MatrixXd measured;  // rows x 3 (u, v, r)
  std::array<double, 3> scale;
  double continuity;  // 0 for the last segment, or one whose successor is not fitted
  std::array<double, Model::kParams> param_scale;

  int Residuals() const { return static_cast<int>((times.size() - 1) * 3 + 3); }

  // The segment simulated from x0 (u, v, r) with parameters theta: the plant's states at each
  // row into `out` (times.size() rows of Plant<Model>::kStates), and the rows simulated.
  // Dynamics: Model, or a type that adds to its Derivative (knot_window_cost.h).
  template <typename T, typename Dynamics = Model>
  size_t Rollout(const T* theta, const T* x0, std::vector<T>& out) const {
    constexpr int N = Plant<Model>::kStates;
    const std::array<T, Model::kParams> pa = Unscale<Model::kParams>(theta, param_scale);
    std::array<T, N> start;
    start.fill(T(0));
    start[3] = x0[0];
    start[4] = x0[1];
    start[5] = x0[2];
    const double* u0 = track->At(times[0]);
    for (int i = 0; i < Model::kInputs; ++i) start[Model::kStates + i] = T(u0[i]);
    OpenLoopSetup setup;
    setup.inputs = track;
    setup.times = times;
    setup.max_step = times.size() > 1 ? (times[1] - times[0]) * 1.0000001 : 1.0;
    out.assign(times.size() * N, T(0));
    std::array<double, Model::kInputs> limits;
    limits.fill(INFINITY);
    return RolloutOpenLoop<Dynamics, T, Steppers::kRk4Only>(setup, start.data(), pa.data(),
                                                            EffectValues<T>{}, limits, out.data());
  }

  template <typename T>
  bool operator()(const T* theta, const T* x0, const T* next, T* res) const {
    constexpr int N = Plant<Model>::kStates;
    std::vector<T> out;
    const size_t rows = Rollout(theta, x0, out);
    int k = 0;
    for (size_t row = 1; row < times.size(); ++row)
      for (int c = 0; c < 3; ++c) {
        // A diverged rollout keeps its last state, so the cost stays finite.
        const size_t use = std::min(row, rows - 1);
        res[k++] = (out[use * N + 3 + c] - T(measured(row, c))) / scale[c];
      }
    const size_t last = rows - 1;
    for (int c = 0; c < 3; ++c)
      res[k++] = continuity * (out[last * N + 3 + c] - next[c]) / scale[c];
    return true;
  }
};

}  // namespace usvid::fossen
