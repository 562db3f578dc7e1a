// The MMG coefficients of a ship estimated from its main particulars, by published empirical
// formulas (docs/model.md#estimates-from-the-particulars gives each with its source and range):
// what a vessel file (simulation/vessel_file.h) does not give is taken from here.
#pragma once

#include <string>
#include <vector>

namespace usvid {

// The main particulars, SI units. Positions are from midship, positive ahead [m].
struct MmgHull {
  double rho = 1025.0;  // [kg/m^3] water
  double L = 0.0;       // [m] length between perpendiculars
  double B = 0.0;       // [m] breadth
  double d = 0.0;       // [m] draft
  double C_b = 0.0;     // [-] block coefficient
  double mass = 0.0;    // [kg]
  double x_G = 0.0;     // [m]
  double D_P = 0.0;     // [m] propeller diameter
  double A_R = 0.0;     // [m^2] rudder area
  double H_R = 0.0;     // [m] rudder span
};

struct MmgEstimate {
  std::string name;    // a coefficient of MmgCoefficients::kNames, or kappa, f_alpha
  double value = 0.0;  // in the nondimensional form the model uses (simulators/mmg_forces.h)
  std::string source;  // "Kijima et al. 1990", ...
};

// Every coefficient but m and I_zG (which are particulars), estimated.
std::vector<MmgEstimate> EstimateMmgCoefficients(const MmgHull& hull);

// The particulars outside the ranges the formulas were fitted on, one sentence each ("C_b 0.45
// is below 0.55, the least of the ships behind Kijima et al. 1990's formulas").
std::vector<std::string> OutsideValidity(const MmgHull& hull);

}  // namespace usvid
