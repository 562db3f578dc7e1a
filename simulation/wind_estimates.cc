#include "simulation/wind_estimates.h"

namespace usvid {

std::vector<MmgEstimate> EstimateWindCoefficients(const WindBody& w) {
  // Fujiwara et al. 1998's regression: each coefficient is linear in ratios of the areas,
  // heights and lengths. The constants are the paper's table (X_ij, Y_ij, N_ij).
  const double L = w.L, B = w.B, A_T = w.A_T, A_L = w.A_L, A_OD = w.A_OD;
  const double C = w.C, C_BR = w.C_BR, H_BR = w.H_BR, H_C = w.H_C;
  const double x0 =
      -0.330 + 0.293 * (B * H_BR / A_T) + 0.0193 * (C / H_C) + 0.682 * (A_OD / (L * L));
  const double x1 = -1.353 + 1.700 * (A_L / (L * B)) + 2.870 * (L * H_C / A_L) -
                    0.463 * (L * H_BR / A_L) - 0.570 * (A_OD / A_L) - 6.640 * (A_T / (L * B)) -
                    0.0123 * (L * L / A_T) + 0.0202 * (L / H_C);
  const double x3 = 0.830 - 0.413 * (A_L / (L * H_BR)) - 0.0827 * (A_L / A_T) -
                    0.563 * (L * H_C / A_L) + 0.804 * (A_OD / A_L) - 5.670 * (A_OD / (L * L)) +
                    0.0401 * (C / H_C) - 0.132 * (C_BR / L);
  const double x5 = 0.0372 - 0.0075 * (A_L / A_OD) - 0.103 * (C_BR / L) + 0.0921 * (A_L / (L * B));
  const double y1 = 0.684 + 0.717 * (C_BR / L) - 3.220 * (C / L) + 0.0281 * (A_L / A_OD) +
                    0.0661 * (C / H_C) + 0.298 * (A_T / (B * H_BR));
  const double y3 = -0.400 + 0.282 * (A_L / (L * B)) + 0.307 * (L * H_C / A_L) +
                    0.0519 * (C_BR / L) + 0.0526 * (B / H_BR) - 0.0814 * (A_OD / A_L) +
                    0.0582 * (A_T / (B * H_BR));
  const double y5 = 0.122 - 0.166 * (A_L / (L * B)) - 0.0054 * (L / H_BR) - 0.0481 * (C_BR / L) -
                    0.0136 * (B * B / A_T) + 0.0864 * (C / L) - 0.0297 * (C * H_C / A_L);
  const double n1 = 0.299 + 1.710 * (C / L) + 0.183 * (L * H_C / A_L) - 1.090 * (A_T / A_L) -
                    0.0442 * (C / H_C) - 0.289 * (A_L / (L * B)) + 4.240 * (A_T / (L * L)) -
                    0.0646 * (B * B / A_T) + 0.0306 * (C_BR / L);
  const double n2 = 0.117 + 0.123 * (C_BR / L) - 0.323 * (C / L) + 0.0041 * (A_L / A_OD) -
                    0.166 * (A_T / (B * B)) - 0.0109 * (L / H_BR) + 0.174 * (A_T / (B * H_BR)) +
                    0.214 * (A_L / (L * B)) - 1.060 * (A_L / (L * L));
  const double n3 =
      0.023 + 0.0385 * (C_BR / L) - 0.0339 * (A_T / (B * H_BR)) + 0.0023 * (A_L / A_T);
  const char* source = "Fujiwara et al. 1998";
  return {{"C_X0", x0, source}, {"C_X1", x1, source}, {"C_X3", x3, source}, {"C_X5", x5, source},
          {"C_Y1", y1, source}, {"C_Y3", y3, source}, {"C_Y5", y5, source}, {"C_N1", n1, source},
          {"C_N2", n2, source}, {"C_N3", n3, source}};
}

}  // namespace usvid
