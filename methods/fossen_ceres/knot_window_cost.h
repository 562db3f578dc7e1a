// A shooting segment's cost (shooting_segment.h's SegmentResidual) for a model whose last
// parameters are the knots of a curve that the model reads two at a time: JetForceModel's
// resistance coefficient c(U), 41 knots of which a 10 s segment visits a few. Ceres' automatic
// differentiation carries one derivative per parameter through every step of the simulation,
// 66 for this model (60 parameters and the segment's 6 states), although all but the knots
// around the segment's speeds have a derivative of exactly 0.
//
// This cost simulates the segment once in doubles, recording the knots each RK4 stage reads, then
// differentiates with Jets over the other parameters, the states and a window of kWindow knots
// (35 derivatives): once for a segment whose speeds span at most kWindow knots, again for each
// further window when they span more. The knots outside the windows are constants of the Jet
// pass, and their Jacobian columns 0. The residuals and the Jacobian are those of
// ceres::AutoDiffCostFunction on the same functor, bit for bit: a Jet's derivatives are computed
// component by component, whatever the Jet's width (KnotWindowCostTest).
//
// The Model declares kFirstKnot and kKnots (the knots last: kParams == kFirstKnot + kKnots) and
// KnotAt(x, env), the first of the two knots its Derivative reads in the state x.
#pragma once

#include <ceres/ceres.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

#include "simulators/vessel.h"

namespace usvid::fossen {

// The Model, recording the knots each call of its Derivative reads (on this thread).
template <typename Model>
struct KnotRecording : Model {
  static std::pair<int, int>& Read() {
    thread_local std::pair<int, int> read;  // the first and the last knot read
    return read;
  }
  template <typename T>
  requires std::is_same_v<T, double>
  static void Derivative(const T* x, const T* in, const T* p, const Environment<T>& env, T* dx) {
    const int k = Model::KnotAt(x, env);
    std::pair<int, int>& read = Read();
    read.first = std::min(read.first, k);
    read.second = std::max(read.second, std::min(k + 1, Model::kKnots - 1));
    Model::Derivative(x, in, p, env, dx);
  }
};

template <typename Model, typename Segment, int kWindow = 10>
class KnotWindowCost final : public ceres::CostFunction {
  static constexpr int kBody = Model::kFirstKnot;   // the parameters before the knots
  static constexpr int kJet = kBody + kWindow + 6;  // body, window, x0 (3), next (3)
  static_assert(Model::kFirstKnot + Model::kKnots == Model::kParams, "the knots come last");
  using Jet = ceres::Jet<double, kJet>;

 public:
  // Takes the segment (its Rollout and its residuals; parameter blocks theta, x0, next of sizes
  // kParams, 3, 3).
  KnotWindowCost(std::unique_ptr<const Segment> segment, int residuals)
      : segment_(std::move(segment)) {
    set_num_residuals(residuals);
    *mutable_parameter_block_sizes() = {Model::kParams, 3, 3};
  }

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    const double* theta = parameters[0];
    const double* x0 = parameters[1];
    const double* next = parameters[2];
    if (jacobians == nullptr) return (*segment_)(theta, x0, next, residuals);
    const auto [first, last] = KnotsRead(theta, x0);
    const int m = num_residuals();
    std::vector<Jet> res(static_cast<size_t>(m));
    std::array<Jet, Model::kParams> theta_jet;
    std::array<Jet, 3> x0_jet, next_jet;
    for (int window = first; window <= last; window += kWindow) {
      const bool states = window == first;  // the body's and states' derivatives: first pass
      for (int i = 0; i < Model::kParams; ++i) {
        const int knot = i - kBody;
        theta_jet[i] = Jet(theta[i]);
        if (i < kBody)
          theta_jet[i].v[i] = 1.0;
        else if (knot >= window && knot < window + kWindow)
          theta_jet[i].v[kBody + knot - window] = 1.0;
      }
      for (int c = 0; c < 3; ++c) {
        x0_jet[c] = Jet(x0[c], kBody + kWindow + c);
        next_jet[c] = Jet(next[c], kBody + kWindow + 3 + c);
      }
      if (!(*segment_)(theta_jet.data(), x0_jet.data(), next_jet.data(), res.data())) return false;
      for (int r = 0; r < m; ++r) {
        const Jet& e = res[r];
        if (states && residuals != nullptr) residuals[r] = e.a;
        if (double* j = jacobians[0]) {
          double* row = j + static_cast<ptrdiff_t>(r) * Model::kParams;
          if (states) {
            for (int i = 0; i < kBody; ++i) row[i] = e.v[i];
            std::fill(row + kBody, row + Model::kParams, 0.0);
          }
          for (int k = window; k < std::min(window + kWindow, last + 1); ++k)
            row[kBody + k] = e.v[kBody + k - window];
        }
        if (!states) continue;
        for (int b = 1; b <= 2; ++b)
          if (double* j = jacobians[b])
            for (int c = 0; c < 3; ++c) j[r * 3 + c] = e.v[kBody + kWindow + 3 * (b - 1) + c];
      }
    }
    return true;
  }

 private:
  // The knots the segment reads at theta: from its simulation in doubles, every RK4 stage's
  // (the same trajectory as the Jets' values, operation for operation).
  std::pair<int, int> KnotsRead(const double* theta, const double* x0) const {
    std::pair<int, int>& read = KnotRecording<Model>::Read();
    read = {Model::kKnots - 1, 0};
    std::vector<double> out;
    segment_->template Rollout<double, KnotRecording<Model>>(theta, x0, out);
    return {std::min(read.first, read.second), read.second};
  }

  std::unique_ptr<const Segment> segment_;
};

}  // namespace usvid::fossen
