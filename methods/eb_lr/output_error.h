// Output-error fit of one mass polynomial of the Eriksen-Breivik model (eb_lr.h, step 3 with
// output_error_mass). For equation i (0: speed U, 1: rate r), with sigma held fixed,
//    x_i' = (tau_i - sigma(U, r)) / m(U, r),   m = sum_j c_j mu_j(U, r),
// each run [first, last] is simulated from the smoothed x_i at `first` (RK4 over each sample
// interval, tau_i held from the sample, the other state linear between its smoothed samples),
// and c minimises the sum over the runs' later samples of (measured x_i - simulated x_i)^2, by
// Gauss-Newton (forward-difference Jacobian) with step halving, from the given c. Noise on the
// measured state leaves this criterion unbiased, unlike the equation error, whose regressors
// carry the noise. Never throws; a simulation that blows up is a refused step.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "methods/eb_lr/monomial.h"
#include "methods/eb_lr/steady_windows.h"

namespace usvid::eb_lr {

struct MassOutputErrorProblem {
  const Eigen::VectorXd& t;         // [s], uniform
  const Eigen::VectorXd& speed;     // smoothed U [m/s]
  const Eigen::VectorXd& rate;      // smoothed r [rad/s]
  const Eigen::VectorXd& measured;  // raw x_i
  const Eigen::VectorXd& input;     // tau_i
  int state;                        // i
  const std::vector<Monomial>& sigma_basis;
  const Eigen::VectorXd& sigma;
  const std::vector<Monomial>& mass_basis;
  const std::vector<SteadyWindow>& runs;  // sample spans [first, last]
  const Eigen::VectorXd& loss_channel;    // q, empty without the thrust's loss
  double thrust_loss = 0.0;               // k: the speed equation's force is tau - k q U - sigma
};

struct MassOutputErrorFit {
  Eigen::VectorXd mass;  // the coefficients c
  double rms = 0.0;      // RMS output error, in x_i's units
  int iterations = 0;
};

MassOutputErrorFit FitMassByOutputError(const MassOutputErrorProblem& problem,
                                        Eigen::VectorXd start);

}  // namespace usvid::eb_lr
