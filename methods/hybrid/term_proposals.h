// The hybrid method's proposals: which terms a registered vessel lacks, by forward orthogonal
// least squares (FROLS, Billings 2013, the structure detection of NARMAX models) on the
// derivative residual d_s = s_dot - f_s(x, u; vessel) of each dynamic state s. The library is
// the constant, each dynamic state and input, their products and |x| x (inputs enter products
// too); no heading or position, so that a term carries over from one maneuver to another. Each step takes the column whose part orthogonal to those
// chosen explains the most of d_s (its error reduction ratio, ERR); the coefficients are the
// least-squares weights of the chosen columns together.
//
// A vessel whose forces scale with speed squared (VesselInfo::speed_scaled_forces, MMG) lacks
// terms of that form: 1/2 rho L d U^2 f(z), z the velocities over the speed (v' = v/U, r' ~ r/U)
// and the inputs given (the rudder angle: the propeller has a model of its own), f of degree
// two (with |z| z). With the surge speed u for U, the columns are u^2, u v, u r, u^2 delta, v^2,
// v r, u v delta, u^2 delta^2, |v| v, ... On the KVLCC2 tests, a constant yaw moment fitted on
// a zig-zag (at 6.7 m/s) is several times too strong in a turning circle, where the speed falls
// to 2.6 m/s; the same moment as u*u carries over (docs/hybrid.md).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "core/dataset.h"
#include "effects/effect.h"

namespace usvid::hybrid {

struct TermProposal {
  Effect term;         // a missing_term: state, term and its least-squares coefficient
  double err = 0.0;    // error reduction ratio: its share of d_s's mean square
};

// Up to `per_state` terms per state of `residual` (rows of `prepared`, whose columns hold the
// states and inputs named), best first within each state. Columns with no part orthogonal to
// those chosen (below 1e-9 of their norm) are skipped; a state whose residual is zero has none.
// `speed`: the surge speed state for a speed-scaled library, "" for the plain one.
std::vector<TermProposal> ProposeTerms(const Dataset& prepared,
                                       const std::map<std::string, Eigen::VectorXd>& residual,
                                       const std::vector<std::string>& inputs, int per_state,
                                       const std::string& speed = "");

}  // namespace usvid::hybrid
