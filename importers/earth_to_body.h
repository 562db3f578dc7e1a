// Body-fixed surge and sway from earth-fixed (north, east) velocities and heading psi [rad]:
//   u =  v_n cos(psi) + v_e sin(psi),   v = -v_n sin(psi) + v_e cos(psi).
#pragma once

#include <Eigen/Core>

namespace usvid {

struct BodyVelocities {
  Eigen::VectorXd u;
  Eigen::VectorXd v;
};

BodyVelocities EarthToBody(const Eigen::VectorXd& vn, const Eigen::VectorXd& ve,
                           const Eigen::VectorXd& psi);

}  // namespace usvid
