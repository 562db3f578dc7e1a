#include "preprocessing/heading_rate.h"

#include <cmath>
#include <numbers>

#include "core/angles.h"
#include "core/error.h"
#include "preprocessing/smoothing_spline.h"

namespace usvid {

Eigen::VectorXd RateFromHeading(const Dataset& data, const std::string& heading) {
  const Channel* c = data.Find(heading);
  if (c == nullptr) throw InputError(data.SourcePrefix() + "no heading column '" + heading + "'");
  if (!c->FullySampled())
    throw InputError(data.SourcePrefix() + "heading '" + heading +
                     "' has empty cells: resample it first");
  return SmoothingSpline(UnwrappedAngle(c->values()), MedianInterval(data.t())).derivative;
}

}  // namespace usvid
