// A rudder's force at the speed of the water it meets (docs/baselines.md#the-rudders-inflow): the
// candidate terms that SINDy's library (preprocessing/regressor_library.h) and GP's variables
// (methods/gp/gp_method.cc, "rudder_inflow") take for a rudder behind a propeller.
//
// The force grows with the square of the rudder's inflow speed, and behind a propeller that
// inflow comes from the hull's wake, which moves with u, and from the propeller's race, which
// moves with its revolutions while it turns ahead (MMG's u_R, Yasukawa & Yoshimura 2015): u_R^2
// is, to first order, a quadratic form in u and n+ = max(n, 0). So the force lies in the span of
// delta times |u| u, u n+ and n+ n+. A propeller turning astern throws its race forward, off the
// rudder. n+ is written (n + |n|), twice n+, since the equation syntax has no max.
#pragma once

#include <string>
#include <vector>

namespace usvid {

struct RudderInflowTerm {
  std::string name;        // a channel-like name: delta_uu, delta_un, delta_nn
  std::string expression;  // in the equation syntax (docs/data.md#equation-syntax)
};

// The terms for the channels among `channels` (states and inputs): none without a rudder angle
// `delta`; delta_uu with u; delta_un and delta_nn with a propeller, `n` [1/s], else `rev`
// [1/min]. A waterjet's `nozzle` is not a rudder: its force is the jet's thrust turned.
std::vector<RudderInflowTerm> RudderInflowTerms(const std::vector<std::string>& channels);

}  // namespace usvid
