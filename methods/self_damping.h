// Whether each identified equation damps or restores its own state: the mean over the training
// rows of d(x')/dx, the state's equation differentiated with respect to the state itself. A
// vessel's surge, sway and yaw each lose energy to the water, so a value >= 0 (no damping, or
// growth) marks a model that will drift or diverge in a free run even where its one-step fit
// looks good; the reference report's GP models of the Esso Osaka runs had none (issue 38).
// The mean can hide a state damped only through another: u' = c - k |v u| is damped on average
// over a zig-zag and not at all running straight, where its speed then grows without bound. So
// the same derivative is read at straight running too (methods/straight_running.h). Identify
// writes both to model.json ("self_damping", "self_damping_straight_running", "undamped";
// docs/data.md#modeljson).
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "core/dataset.h"
#include "core/model_view.h"

namespace usvid {

// state -> mean d(x')/dx [1/s] over the rows of `data` where every variable of its equation is
// sampled; a state whose equation reads a variable the data lack, or has no such row, is left
// out. Central differences, step 1e-6 x (|x| + the state's RMS), in double; on a long log every
// k-th row, at most 20000.
std::map<std::string, double> SelfDamping(const EquationList& equations, const Dataset& data);

// state -> d(x')/dx [1/s] at straight running (straight_running.h; the mean over the two points
// of a state a mirror turns over), the levels read over the samples of `data`; left out as above.
std::map<std::string, double> StraightRunningDamping(const EquationList& equations,
                                                     const Dataset& data);

}  // namespace usvid
