#include "core/derived_channels.h"

#include <cmath>

namespace usvid {

void AddSpeedAndCourse(Dataset& data) {
  if (!data.Has("u") || !data.Has("v")) return;
  const Channel& u = data.Get("u");
  const Channel& v = data.Get("v");
  if (!data.Has("U")) {
    Eigen::VectorXd speed = (u.values.array().square() + v.values.array().square()).sqrt().matrix();
    data.Set("U", std::move(speed), u.sampled && v.sampled);
  }
  if (!data.Has("chi") && data.Has("psi")) {
    const Channel& psi = data.Get("psi");
    Eigen::VectorXd course(data.rows());
    for (Eigen::Index k = 0; k < data.rows(); ++k)
      course(k) = psi.values(k) + std::atan2(v.values(k), u.values(k));
    data.Set("chi", std::move(course), u.sampled && v.sampled && psi.sampled);
  }
}

}  // namespace usvid
