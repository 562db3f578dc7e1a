#include "simulation/mmg_estimates.h"

#include <cmath>
#include <cstdio>
#include <numbers>

namespace usvid {
namespace {

std::string Format(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3g", x);
  return b;
}

}  // namespace

namespace {

// The hull's ratios every formula below takes.
struct HullRatios {
  double k;    // aspect ratio of the hull as a wing, 2 d / L
  double cbl;  // C_b B / L
  double lb, db;
  double m;  // m' = rho V / (rho/2 L^2 d)
  double x_G;
};

HullRatios RatiosOf(const MmgHull& h) {
  const double cbl = h.C_b * h.B / h.L;
  return {2.0 * h.d / h.L, cbl, h.L / h.B, h.d / h.B, 2.0 * cbl, h.x_G / h.L};
}

void Add(std::vector<MmgEstimate>& e, const char* name, double value, const char* source) {
  e.push_back({name, value, source});
}

// Added masses: Motora's charts as fitted by Zhou, Yan & Feng (1983), quoted by Sukas, Kinaci
// & Bal (2019), over m'. Returns m_x and m_y, which the hull derivatives take.
struct AddedMasses {
  double m_x, m_y;
};

AddedMasses AddAddedMasses(const MmgHull& h, const HullRatios& q, std::vector<MmgEstimate>& e) {
  const char* zhou = "Zhou et al. 1983";
  const double lb = q.lb, db = q.db;
  const double m_x =
      q.m *
      (0.398 + 11.97 * h.C_b * (1 + 3.73 * db) - 2.89 * h.C_b * lb * (1 + 1.13 * db) +
       0.175 * h.C_b * lb * lb * (1 + 0.541 * db) - 1.107 * lb * db) /
      100.0;
  const double m_y =
      q.m * (0.882 - 0.54 * h.C_b * (1 - 1.6 * db) - 0.156 * (1 - 0.673 * h.C_b) * lb +
             0.826 * db * lb * (1 - 0.678 * db) - 0.638 * h.C_b * db * lb * (1 - 0.669 * db));
  const double j =
      (33.0 - 76.85 * h.C_b * (1 - 0.784 * h.C_b) + 3.43 * lb * (1 - 0.63 * h.C_b)) / 100.0;
  Add(e, "m_x", m_x, zhou);
  Add(e, "m_y", m_y, zhou);
  Add(e, "J_z", q.m * j * j, zhou);
  return {m_x, m_y};
}

// Resistance: ITTC-57 friction at Froude number 0.15, form factor 1.2 of a full hull, wetted
// surface by Mumford's S = 1.7 L d + V / d; the wave resistance of a slow full hull is left
// out.
void AddResistance(const MmgHull& h, std::vector<MmgEstimate>& e) {
  const double speed = 0.15 * std::sqrt(9.81 * h.L);
  const double nu = h.rho < 1010.0 ? 1.14e-6 : 1.19e-6;  // [m^2/s] fresh or sea water, 15 C
  const double re = speed * h.L / nu;
  const double c_f = 0.075 / std::pow(std::log10(re) - 2.0, 2);
  const double wetted = 1.7 * h.L * h.d + h.C_b * h.L * h.B;  // V / d = C_b L B
  Add(e, "R_0", 1.2 * c_f * wetted / (h.L * h.d), "ITTC 1957 friction line, form factor 1.2");
}

// Surge, sway and yaw derivatives. Linear: Kijima et al. 1990; the pure cubic terms (v^3,
// r^3): Yoshimura & Masumoto 2012; the cross terms (v^2 r, v r^2): Kijima et al. 1990's beta-r
// terms, fitted on full-form merchant hulls. Yoshimura & Masumoto's cross terms, from slender
// ships (C_b up to 0.8), have the wrong sign for full hulls (Y_vvr, N_vrr) or twice the size
// (N_vvr: KVLCC2 -0.53 against -0.29; Kijima's -0.14), and turned the Esso Osaka and KVLCC2
// circles 30-56 % too wide (docs/model.md#estimates-from-the-particulars). With v' = -beta:
// Y_vvr = Y_bbr, Y_vrr = -Y_brr, N_vvr = N_bbr, N_vrr = -N_brr.
void AddHullDerivatives(const MmgHull& h, const HullRatios& q, const AddedMasses& added,
                        std::vector<MmgEstimate>& e) {
  const double m_x = added.m_x, m_y = added.m_y;
  const char* yoshimura = "Yoshimura & Masumoto 2012";
  const char* kijima = "Kijima et al. 1990";
  const double k = q.k, cbl = q.cbl, lb = q.lb, db = q.db;
  Add(e, "X_vv", 1.15 * cbl - 0.18, yoshimura);
  Add(e, "X_vr", m_y - 1.91 * cbl + 0.08, yoshimura);
  Add(e, "X_rr", -0.085 * cbl + 0.008 + q.x_G * m_y, yoshimura);
  Add(e, "X_vvvv", -6.68 * cbl + 1.1, yoshimura);
  Add(e, "Y_v", -(0.5 * std::numbers::pi * k + 1.4 * cbl), kijima);
  Add(e, "Y_r", q.m + m_x - 1.5 * cbl, kijima);
  Add(e, "Y_vvv", -0.185 * lb + 0.48, yoshimura);
  Add(e, "Y_vvr", 1.5 * db * h.C_b - 0.65, kijima);
  Add(e, "Y_vrr", -5.95 * db * (1 - h.C_b), kijima);
  Add(e, "Y_rrr", -0.051, yoshimura);
  Add(e, "N_v", -k, kijima);
  Add(e, "N_r", -0.54 * k + k * k, kijima);
  Add(e, "N_vvv", -(0.66 - 0.69 * h.C_b), yoshimura);
  Add(e, "N_vvr", -(57.5 * cbl * cbl - 18.4 * cbl + 1.6), kijima);
  Add(e, "N_vrr", 0.5 * db * h.C_b - 0.05, kijima);
  Add(e, "N_rrr", 0.25 * cbl - 0.056, yoshimura);
}

// Propeller: Taylor's wake fraction of a single screw, a thrust deduction of 0.6 w_P0, and,
// with no formula from the particulars, KVLCC2's open-water curve and wake in drift
// (Yasukawa & Yoshimura 2015). Rudder-hull interaction of a full single-screw hull: KVLCC2's;
// the published regressions on C_b reproduce no known ship (docs/model.md#vessel-files). Rudder
// lift gradient from the aspect ratio H_R^2 / A_R: Fujii & Tsuda 1961.
void AddPropellerAndRudder(const MmgHull& h, std::vector<MmgEstimate>& e) {
  const char* kvlcc2 = "KVLCC2's, Yasukawa & Yoshimura 2015: no formula from the particulars";
  const char* esso = "Esso Osaka's, Miyauchi et al. 2022";
  const double w = 0.5 * h.C_b - 0.05;
  Add(e, "t_P", 0.6 * w, "0.6 w_P0, a single screw's rule of thumb");
  Add(e, "w_P0", w, "Taylor's single-screw wake");
  Add(e, "k_0", 0.2931, kvlcc2);
  Add(e, "k_1", -0.2753, kvlcc2);
  Add(e, "k_2", -0.1385, kvlcc2);
  Add(e, "C_1", 2.0, kvlcc2);
  Add(e, "C_2_pos", 1.6, kvlcc2);
  Add(e, "C_2_neg", 1.1, kvlcc2);
  Add(e, "t_R", 0.387, kvlcc2);
  Add(e, "a_H", 0.312, kvlcc2);
  Add(e, "x_H", -0.464, kvlcc2);
  Add(e, "gamma_R_neg", 0.395, kvlcc2);
  Add(e, "gamma_R_pos", 0.640, kvlcc2);
  Add(e, "l_R", -0.710, kvlcc2);
  Add(e, "epsilon", 1.09, kvlcc2);
  Add(e, "K_Ta_0", -0.175, esso);
  Add(e, "K_Ta_1", 0.33, esso);
  Add(e, "K_Ta_min", -0.251, esso);
  Add(e, "kappa", 0.50, kvlcc2);
  const double aspect = h.H_R * h.H_R / h.A_R;
  Add(e, "f_alpha", 6.13 * aspect / (aspect + 2.25), "Fujii & Tsuda 1961");
}

}  // namespace

std::vector<MmgEstimate> EstimateMmgCoefficients(const MmgHull& h) {
  const HullRatios q = RatiosOf(h);
  std::vector<MmgEstimate> e;
  const AddedMasses added = AddAddedMasses(h, q, e);
  AddResistance(h, e);
  AddHullDerivatives(h, q, added, e);
  AddPropellerAndRudder(h, e);
  return e;
}

std::vector<std::string> OutsideValidity(const MmgHull& h) {
  // The merchant hulls behind Kijima et al. 1990 and Motora's charts (Zhou et al. 1983).
  std::vector<std::string> out;
  auto check = [&](const char* what, double value, double lo, double hi) {
    if (value < lo || value > hi)
      out.push_back(std::string(what) + " " + Format(value) + " is outside " + Format(lo) + "-" +
                    Format(hi) +
                    ", the range of the merchant hulls behind the estimated coefficients "
                    "(Kijima et al. 1990, Zhou et al. 1983): given coefficients are safer");
  };
  check("C_b", h.C_b, 0.5, 0.85);
  check("L/B", h.L / h.B, 4.5, 8.0);
  check("B/d", h.B / h.d, 2.0, 4.0);
  return out;
}

}  // namespace usvid
