// Whether a proposed term is a coefficient the refit already frees, in another dress. A missing
// term adds c * term(x, u) to a state's derivative; a freed coefficient p changes that
// derivative by (df/dp) dp. Where the two columns have the same shape over the rows, the term
// is not missing: it is a second p, fitted beside p without the prior that holds p near its
// published value. On the Esso Osaka runs the hybrid kept r' += -0.151 u v beside a freed N_v,
// whose yaw moment is 1/2 rho L^2 d U^2 N_v v/U = (...) U v, and before it u' += -0.124 u^2
// beside a freed R_0 (docs/hybrid.md#a-term-that-is-a-freed-coefficient).
#pragma once

#include <string>
#include <vector>

#include "core/dataset.h"
#include "methods/hybrid/term_proposals.h"
#include "simulation/vessel_ref.h"

namespace usvid::hybrid {

struct CoefficientShape {
  std::string parameter;  // the freed coefficient whose shape is closest ("" if none is free)
  double cosine = 0.0;    // |cos| of the angle between the two columns over the rows, in [0, 1]
};

// For each proposal, the freed parameter (of `names`, at `params`) whose derivative column
// df_s/dp on `prepared` (DerivativeResidual's rows; central differences of relative step 1e-4)
// is closest in shape to the proposal's term column, both uncentred (a force through zero).
// Rows where either is not finite are left out.
std::vector<CoefficientShape> ClosestFreeCoefficient(const VesselRef& vessel,
                                                     const Dataset& prepared,
                                                     const std::vector<std::string>& names,
                                                     const std::vector<double>& params,
                                                     const std::vector<std::string>& free,
                                                     const std::vector<TermProposal>& proposals);

}  // namespace usvid::hybrid
