// Eriksen & Breivik (2017) linear regression of the 2-DOF high-speed model (docs/model.md#eb2dof),
// method `eb-lr`. State x = [U r] (speed [m/s], rate of turn [rad/s]), input tau = [tau_m
// tau_delta] (thrust and yaw commands in the data's units, e.g. throttle [-], nozzle [rad]):
//   M(x) x' + sigma(x) = tau,   M(x) = diag(m_U(x), m_r(x)),
//   sigma_U = sum_j a_j phi_j(U, r),   sigma_r = sum_j b_j psi_j(U, r),
//   m_U     = sum_j c_j mu_j(U, r),    m_r     = sum_j d_j nu_j(U, r),
// each basis function a monomial (monomial.h). Defaults are eb2dof's form: sigma_U on U, U^2,
// U^3, r^2; sigma_r on r, U r, r^3; m_U and m_r on 1, U. Units of the coefficients follow.
//
// Data: raw measurements, fully sampled on a uniform grid (resample multi-rate logs first and
// shift the inputs by a known delay, as the method `eb-lr` does, eb_lr_method.cc; do not smooth:
// the method averages and estimates the noise itself), one record or several stretches of one
// grid (records joined, gaps: nothing is smoothed, windowed or integrated across their joins).
// Inputs are zero-order held from each sample (the command of row k acts until row k + 1). A
// step grid (maneuvers/step_grid.h) is the intended experiment.
//  1. Steady windows, from the data alone (steady_windows.h): stretches of constant input where
//     the local slopes of U and r are within their noise or below a relative rate.
//  2. sigma: each window gives one row at its mean state,
//        sigma(x_mean) = mean tau - (1/T) int M(x) dx,
//     the last term (what a not quite settled window still accelerates) 0 on the first pass;
//     linear least squares per equation.
//  3. M: each run of samples outside the windows, reaching transient_margin_s into the windows
//     around it, is cut into pieces of transient_window_s; each piece is a row
//        sum_j c_j int mu_j(x) dU = int (tau_m - sigma_U(x)) dt        (and so for r),
//     the integral form of M(x) x' = tau - sigma(x) (the equation error averaged over a piece,
//     so no pointwise derivatives), on the states smoothed by the spline with the inputs' step
//     breaks (preprocessing/derivative.h); linear least squares. With output_error_mass the
//     result then starts a Gauss-Newton fit of the same coefficients to the measured state over
//     those runs, each simulated from its start (RK4, the other state from the smoothed data):
//     noise on the regressors biases and scatters equation error, not output error.
//  4. Steps 2 and 3 are repeated `refinements` times.
// With lower_order, a record with fewer steady windows than a sigma basis has terms, or windows
// that do not excite or separate some of them, is fitted on the terms, in the basis's order,
// that they do excite (each window's mean reaches 1 % of the term's largest value over the data)
// and separate (rank at 1e-6), at most one fewer than the windows: the polynomial's order
// lowered, and said in details.warnings. An
// equation whose windows excite none of its terms (no steady turn for sigma_r) takes its first
// term from the transients instead, jointly with its mass (the rows of step 3 with the term's
// integral int phi dt as one more column). Without lower_order, those records are refused.
// Equations (docs/data.md#modeljson): speed -> "(tau_m - (a1*U + ...)) / (c1 + c2*U)", and so
// for r; with a thrust_loss_channel q, sigma_U's sum ends with "k*q*U".
// A mass that is not positive over the data is reported in details.warnings, not thrown.
//
// Throws InputError: a missing, not fully sampled or non-finite channel; a non-uniform time
// grid; a constant input (the thrust allowed with constant_thrust); a bad option (named); no
// steady window at all; without lower_order, fewer steady windows than a sigma basis has terms,
// or windows that do not separate a term (named); fewer transient pieces than M terms.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "core/dataset.h"
#include "core/stretches.h"
#include "methods/eb_lr/monomial.h"
#include "methods/eb_lr/steady_windows.h"

namespace usvid::eb_lr {

// The name --method and suites give it (methods/method_list.h registers it).
inline constexpr std::string_view kMethodName = "eb-lr";

struct EbLrOptions {
  std::vector<Monomial> sigma_speed_basis = {{1, 0}, {2, 0}, {3, 0}, {0, 2}};
  std::vector<Monomial> sigma_rate_basis = {{0, 1}, {1, 1}, {0, 3}};
  std::vector<Monomial> mass_speed_basis = {{0, 0}, {1, 0}};
  std::vector<Monomial> mass_rate_basis = {{0, 0}, {1, 0}};
  SteadyWindowOptions steady;       // step 1
  double transient_window_s = 2.0;  // [s] step 3
  double transient_margin_s = 1.0;  // [s] step 3
  bool output_error_mass = false;   // step 3
  int refinements = 2;              // step 4
  // A thrust that falls with speed: sigma_U gains the column q U of a channel q, so that the
  // speed equation's force is tau_m - k q U - sigma_U(U, r). A waterjet's net thrust is its
  // jet's momentum less the inlet's, rho Q (V_j - (1 - w) U): with tau_m the jet momentum
  // (tau_x of --forces waterjet), q is the jet flow Q (jet_flow). Empty: no loss term.
  std::string thrust_loss_channel;
  // The commands that are held at each step (thrust, yaw), when the inputs are not: forces
  // derived from measured actuator states slew to each new value and carry the sensors' noise,
  // so the steady windows and the spline's step breaks follow the commands. Empty: the inputs.
  std::vector<std::string> held_inputs;
  // Fewer steady windows than the bases need: fit the terms they separate (above), or refuse.
  bool lower_order = false;
  // A record whose thrust is held at one level (a zig-zag, a turning circle): fitted, sigma_U
  // then only on the speeds that level reaches, or refused (a step grid steps both inputs).
  bool constant_thrust = false;
};

struct EbLrIdentification {                              // the shape of gp::GpIdentification
  nlohmann::json equations = nlohmann::json::object();   // state -> expression of its derivative
  nlohmann::json parameters = nlohmann::json::object();  // "sigma_U.U*U", "m_r.1", ... -> value
  nlohmann::json details = nlohmann::json::object();     // steady windows, residuals, noise
};

// One record on one uniform grid.
EbLrIdentification IdentifyWithEbLr(const Dataset& data, const std::string& speed,
                                    const std::string& rate, const std::string& thrust_input,
                                    const std::string& yaw_input, const EbLrOptions& options);

// The stretches of one grid (core/stretches.h: records joined, or a record with gaps), each
// uniform with the same step.
EbLrIdentification IdentifyWithEbLr(const Dataset& data, const std::vector<Stretch>& stretches,
                                    const std::string& speed, const std::string& rate,
                                    const std::string& thrust_input, const std::string& yaw_input,
                                    const EbLrOptions& options);

}  // namespace usvid::eb_lr
