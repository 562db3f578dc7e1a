#include "importers/earth_to_body.h"

namespace usvid {

BodyVelocities EarthToBody(const Eigen::VectorXd& vn, const Eigen::VectorXd& ve,
                           const Eigen::VectorXd& psi) {
  const Eigen::ArrayXd c = psi.array().cos();
  const Eigen::ArrayXd s = psi.array().sin();
  return {(vn.array() * c + ve.array() * s).matrix(), (-vn.array() * s + ve.array() * c).matrix()};
}

}  // namespace usvid
