// What a method fits, written as a multiple-shooting problem on a vessel's simulator (refit's,
// methods/refit), so that a design study can compute its Fisher information, and what the
// method needs of a maneuver before it can fit at all.
//
//  - refit: the vessel's own free coefficients, with refit's prior (relative sd 0.5); every
//    registered vessel.
//  - fossen-ceres on odin3dof: its model is that vessel's 10 parameters; no prior, fossen-ceres'
//    10 s segments.
//  - eb-lr on eb2dof: eb-lr's default basis is eb2dof's form (methods/eb_lr/eb_lr.h), so its 11
//    coefficients are the simulator's. The shooting problem's information is what an efficient
//    output-error fit of that model would reach; eb-lr is not one (its sigma comes from the
//    steady windows alone, its masses from the transients), and its own covariance comes from
//    eb_lr_information.h. Named as eb-lr writes them ("sigma_U.U*U").
//    Its own covariance is in eb_lr_information.h: it needs the steady windows eb-lr finds, so
//    eb-lr is fitted once to a noisy run of the trial (Probe). A maneuver without steady
//    windows or two stepped inputs is not usable, and the probe says why in eb-lr's words.
//
// Throws InputError: an unknown vessel or method, gp or sindy (no parameters), fossen-ceres
// on a vessel but odin3dof, eb-lr on a vessel but eb2dof.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/dataset.h"
#include "methods/refit/refit.h"
#include "simulation/vessel_ref.h"

namespace usvid::design {

struct MethodProblem {
  RefitOptions refit;              // free parameters (simulator names), prior, segments
  std::vector<std::string> names;  // each free parameter as the method's model.json names it
};

MethodProblem MethodProblemOf(const VesselRef& vessel, const std::string& method);

struct Probe {
  std::string unusable;   // why the method cannot fit the trial; "" when it can
  nlohmann::json model;   // the method's model.json on the run (eb-lr: its steady windows)
};

// eb-lr fitted to `data` (a noisy run of the trial). The shooting fits take any record and are
// not probed (an empty probe).
Probe ProbeFit(const VesselRef& vessel, const std::string& method, const Dataset& data);

}  // namespace usvid::design
