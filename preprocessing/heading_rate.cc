#include "preprocessing/heading_rate.h"

#include <cmath>
#include <numbers>

#include "core/error.h"
#include "preprocessing/smoothing_spline.h"

namespace usvid {

Eigen::VectorXd RateFromHeading(const Dataset& data, const std::string& heading) {
  const Channel* c = data.Find(heading);
  if (c == nullptr) throw InputError(data.SourcePrefix() + "no heading column '" + heading + "'");
  if (!c->sampled.all())
    throw InputError(data.SourcePrefix() + "heading '" + heading +
                     "' has empty cells: resample it first");
  Eigen::VectorXd psi = c->values;
  for (Eigen::Index k = 1; k < psi.size(); ++k) {
    const double step = psi(k) - psi(k - 1);
    psi(k) -= 2 * std::numbers::pi * std::round(step / (2 * std::numbers::pi));
  }
  return SmoothingSpline(psi, MedianInterval(data.t())).derivative;
}

}  // namespace usvid
