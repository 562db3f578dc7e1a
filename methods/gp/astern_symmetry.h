// A hull's damping of sway and yaw, written with |u| where GP wrote u.
//
// Why. The hydrodynamic force on a hull scales with the square of its speed through the water,
// and its sway and yaw damping with the speed's magnitude: MMG's N = 1/2 rho L^2 d U^2 N'_r r',
// with r' = r L / U, is N'_r (1/2 rho L^3 d) |U| r. Fitted on a record that runs ahead almost
// throughout, a term r*u and a term r*|u| are the same column, and GP's search, which draws u
// far more often than abs(u), writes the product with u. Astern, that damping turns into
// growth: on the Esso Osaka runs GP's seed 2 chose r' = -0.368 u r - 0.0193 r, which drives r
// below u = -0.052 m/s, and its free run of a random run that goes to -0.12 m/s astern diverged
// (docs/real-data.md). Every term of x' (x a state other than u) in which x appears has each u
// in it written as abs(u), before its weight is fitted; ahead that changes no number.
//
// Only where it can matter: when u is a state that goes below 0 in the training record (a log
// that starts at rest, or reverses). On a record that never goes astern the equations are left
// as searched. abs is written whether or not it is among the search's operators: it is the
// hull's physics, not a step of the search (at GP's default +, -, * seeds 2 and 3 damped yaw
// with u r and diverged on that random run; seed 2 now holds).
#pragma once

#include <string>
#include <vector>

#include "methods/gp/tree.h"

namespace usvid::gp {

// `tree` (a sum of terms, SplitTerms) with every variable `surge` in a term that reads the
// variable `self` wrapped in abs, unless it already is; `self` == `surge` leaves it alone.
Tree AsternSymmetric(const Tree& tree, int surge, int self);

}  // namespace usvid::gp
