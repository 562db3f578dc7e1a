// Beyond the catalogue: when no effect explains what the nominal simulation gets wrong, a sparse
// regression proposes the missing terms. For every measured dynamic state s (not a position or
// heading), on the preprocessed data (smoothed states, derivatives s_dot):
//   d_s = s_dot - f_s(x, u; nominal),
// and two regressions fit d_s on the training part, with the dynamic states and inputs as
// variables, plus cos psi and sin psi when the heading is measured (earth-fixed forces):
//  - SINDy (methods/sindy), on the library of constant, products, |x| x and inputs;
//  - GP-SR (methods/gp, operators +, -, *, abs; a small search: population 300, 20
//    generations, seeded), which may find a form outside that library (|v| r, v^3, u |u| v).
// A proposal is kept when it explains at least 30 % of d_s's mean square on the held-out part
// (its mean square, not its variance: a missing constant force is all mean). Each proposal's
// terms become missing_term candidates (diagnose.cc), so a term both propose is fitted once.
#pragma once

#include <vector>

#include "diagnosis/diagnose.h"
#include "simulation/vessel_simulator.h"

namespace usvid::diagnosis {

std::vector<DiscoveredTerms> DiscoverMissingTerms(const Dataset& data, const VesselSimulator& sim,
                                                  const EffectFitter& fitter,
                                                  const std::vector<double>& params,
                                                  const MeasuredData& measured);

}  // namespace usvid::diagnosis
