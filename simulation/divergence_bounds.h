// When a free run has diverged, per channel. A state with its own dynamics (a velocity, a rate,
// an actuator state) has diverged when it leaves ten times the largest magnitude the data show
// of it (of at least 1e-3 in its unit, for a channel the data hold at zero); positions and
// heading, the integrals of those, only when they are no longer finite (a model that turns where
// the vessel went straight is wrong, not divergent). One bound for all channels would let a
// velocity grow to ten times the position range before the run counted as diverged. Scoring's
// free runs (metrics/free_run.h) and the hybrid's check of its terms (methods/hybrid) use it.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/dataset.h"

namespace usvid {

class DivergenceBounds {
 public:
  DivergenceBounds(const std::vector<std::string>& channels, const Dataset& data);
  // The index of the first channel of `x` out of its bound, or -1.
  int Exceeded(const Eigen::VectorXd& x) const;
  double Bound(size_t i) const { return bounds_[i]; }

 private:
  std::vector<double> bounds_;  // +infinity: only finiteness checked
};

}  // namespace usvid
