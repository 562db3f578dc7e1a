// Ceres cost of one segment with a free initial state: the effect sizes theta (K values, shared
// by all segments) and the vessel state at the segment's first row (V::kStates values; the
// states the data do not measure are held constant by the caller). The first row's residual
// ties the initial state to the measurement, so the noise of a single sample no longer sets a
// segment's course: this is what makes a gyro bias of the size of the noise identifiable on
// an unstable hull.
#pragma once

#include <ceres/ceres.h>

#include "diagnosis/effect_search.h"
#include "diagnosis/reset_rollout.h"

namespace usvid::diagnosis {

template <Vessel V, int K>
struct SegmentCost {
  const MeasuredData* data;
  const Part* part;
  size_t segment;
  std::array<double, V::kParams> params;
  const EffectSearch* search;  // outlives the problem

  int Residuals() const {
    const auto [a, b] = SegmentRows(*part, segment);
    return static_cast<int>((b - a) * static_cast<Eigen::Index>(data->channels.size()));
  }

  template <typename T>
  bool operator()(const T* theta, const T* x0, T* residual) const {
    EffectValues<T> e = CastValues<T>(data->base);
    ApplySizes(*search, theta, e);
    const EffectPlant<V, T> plant(*data, params, e);
    SegmentRollout<V, T>(*data, *part, segment, plant, x0, residual);
    return true;
  }

  static ceres::CostFunction* Create(const MeasuredData& data, const Part& part, size_t segment,
                                     const std::array<double, V::kParams>& params,
                                     const EffectSearch& search) {
    auto* functor = new SegmentCost{&data, &part, segment, params, &search};
    const int residuals = functor->Residuals();
    return new ceres::AutoDiffCostFunction<SegmentCost, ceres::DYNAMIC, K, V::kStates>(functor,
                                                                                       residuals);
  }
};

}  // namespace usvid::diagnosis
