// SINDy (Brunton, Proctor & Kutz 2016): each state derivative as a sparse linear combination of
// the candidate library of preprocessing/regressor_library.h,
//   x_i' = sum_j xi_ij theta_j(x, u),   theta = [1, x_k, x_k x_l, |x_k| x_k, u_m]
// (states as variables, inputs linear only), found by sequentially thresholded ridge regression
// (STRidge, Rudy et al. 2017) on normalised data: every column and the target scaled to unit RMS,
//   w = argmin |y - A w|^2 + ridge sum_j |a_j|^2 w_j^2,
// then repeatedly the terms with |w_j| < threshold are cut and the rest refitted, until the
// support stops changing (or max_iterations); the terms kept are refitted by plain least squares
// (Rudy's debiasing step), so the ridge only steers which terms survive. The threshold is chosen
// per state by k-fold cross-validation over contiguous blocks of the series
// (preprocessing/splits.h, never random samples): the one with the smallest mean held-out
// derivative MSE, or the largest (sparsest) whose mean is within one standard error of that (the
// 1-SE rule); the model is refitted on all rows with it. Over several records (or stretches
// between gaps) each is cut into the folds' blocks, so every fold holds out a share of each.
//
// With SindyOptions::weak_window_s > 0 the rows regressed are not the grid's derivatives but the
// weak form over windows of that length (methods/sindy/weak_form.h): the same coefficients,
// from the measured state without differentiating it.
//
// Units: a coefficient is in the derivative's units over the term's (1/s for u' on u, 1/kg for
// u' on tau_x [N]); thresholds are dimensionless (fractions of the target's RMS per unit-RMS
// column); held-out errors are in the derivative's units squared.
//
// The equations are in the equation syntax of docs/data.md#equation-syntax
// ("0.5 + 0.01*u - 0.049*abs(u)*u + 0.0002*tau_x", coefficients written to round-trip exactly);
// they parse with core/expression.h and evaluate to PredictWithSindy (to rounding: the parser
// multiplies c*v*r as (c*v)*r).
//
// Throws InputError for a missing or non-finite channel, fewer rows (or weak-form windows) than
// folds x 10, folds < 2, max_iterations < 1, a negative or non-finite ridge, threshold or
// window, no states, or an empty library.
#pragma once

#include <string_view>

#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "preprocessing/pipeline.h"
#include "preprocessing/regressor_library.h"

namespace usvid::sindy {

// The name --method and suites give it (methods/method_list.h registers it).
inline constexpr std::string_view kMethodName = "sindy";

struct SindyOptions {
  LibraryOptions library;
  // Relative ridge (scaled by the column norms) during thresholding. It should be at least the
  // squared relative noise of the library columns: directions of the normalised library with
  // less variance than that are noise, and an unpenalised pair of nearly equal columns (u*u and
  // abs(u)*u where u is rarely negative) takes large cancelling weights that no threshold cuts.
  // 1e-4 (1 % noise); 1e-6 leaves such pairs in odin3dof's sway equation at 0.5 % noise.
  double ridge = 1e-4;
  // Candidates for the coefficient threshold on normalised columns (unit RMS); empty: a log grid
  // from 1e-4 to 1, five points a decade.
  std::vector<double> thresholds;
  int folds = 5;  // threshold chosen by held-out error over contiguous-block folds
  // true: the largest threshold within one standard error of the best (sparser); false: the
  // threshold with the smallest held-out error.
  bool one_standard_error = true;
  int max_iterations = 20;
  // > 0: regress the weak form over windows of this length [s] (methods/sindy/weak_form.h)
  // instead of the derivatives; 0: the derivatives "<state>_dot".
  double weak_window_s = 0.0;
};

struct SindyIdentification {
  nlohmann::json equations = nlohmann::json::object();   // state -> expression of its derivative
  nlohmann::json parameters = nlohmann::json::object();  // "<state>.<term>" -> coefficient
  // Per state: chosen threshold, held-out MSE (mean and standard error over folds) and number of
  // terms per candidate threshold, the library, the terms kept, r2 on all rows.
  nlohmann::json details = nlohmann::json::object();
};

// One equation per state in `states` (target "<state>_dot" in prepared.data); the library is
// built from `variables` (states that enter the dynamics, e.g. the msd's position x, which needs
// no equation of its own) and `inputs`.
SindyIdentification IdentifyWithSindy(const PreparedData& prepared,
                                      const std::vector<std::string>& states,
                                      const std::vector<std::string>& variables,
                                      const std::vector<std::string>& inputs,
                                      const SindyOptions& options);

// STRidge at one threshold on all rows: weights in the columns' own units, exactly 0 for the
// terms cut. No input checks (IdentifyWithSindy makes them).
Eigen::VectorXd StRidge(const Eigen::MatrixXd& columns, const Eigen::VectorXd& target,
                        double threshold, double ridge, int max_iterations);

// The identified right-hand side of `state` at every row of `data`: the library (built as
// IdentifyWithSindy built it) times the coefficients in id.parameters, summed in library order.
// Throws InputError naming a channel the data lack.
Eigen::VectorXd PredictWithSindy(const SindyIdentification& id, const std::string& state,
                                 const Dataset& data, const std::vector<std::string>& variables,
                                 const std::vector<std::string>& inputs,
                                 const LibraryOptions& library);

// The default threshold grid: 10^(-4 + k / 5), k = 0 .. 20.
std::vector<double> DefaultThresholds();

}  // namespace usvid::sindy
