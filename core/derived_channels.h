// Speed over ground and course from body velocities, for data that have u, v and psi but not
// U and chi (odin3dof logs; the 2-DOF models need them):
//   U = sqrt(u^2 + v^2),   chi = psi + atan2(v, u).
// Adds the channels only where they are missing; a row is sampled where u, v (and psi) are.
#pragma once

#include "core/dataset.h"

namespace usvid {

void AddSpeedAndCourse(Dataset& data);

}  // namespace usvid
