// The ten wind-force coefficients of simulators/wind_force.h estimated from the body above the
// water, by Fujiwara, Ueno & Nimura's regression over wind-tunnel tests of merchant ships (1998,
// J Soc Naval Archit Japan 183, 77-90). A vessel file's `wind` section gives the areas and
// heights (simulation/vessel_file.h); docs/model.md#wind gives the formulas.
#pragma once

#include <vector>

#include "simulation/mmg_estimates.h"

namespace usvid {

// The body above the water, SI units. Positions are from midship, positive ahead [m]; heights
// from the waterline [m].
struct WindBody {
  double L = 0.0;     // [m] length (L_pp)
  double B = 0.0;     // [m] breadth
  double A_T = 0.0;   // [m^2] transverse projected area
  double A_L = 0.0;   // [m^2] lateral projected area
  double A_OD = 0.0;  // [m^2] lateral projected area of the superstructure and deck cargo
  double C = 0.0;     // [m] centre of A_L from midship
  double C_BR = 0.0;  // [m] centre of A_OD from midship
  double H_BR = 0.0;  // [m] height of the superstructure's top (the bridge)
  double H_C = 0.0;   // [m] height of the centre of A_L
};

// C_X0 ... C_N3 (WindCoefficients::kNames), each with its source.
std::vector<MmgEstimate> EstimateWindCoefficients(const WindBody& body);

}  // namespace usvid
