// Candidate regressors for equation-error fits (delay scans, SINDy): from state channels x and
// input channels u, the columns 1, x_i, x_i x_k (i <= k), |x_i| x_i, u_j and, when asked, the
// input products x_i u_j, u_j u_m (j <= m) and |u_j| u_j (a ship's rudder force grows with
// u delta at a given speed, its thrust with |n| n) and a rudder's force at its inflow speed
// (preprocessing/rudder_inflow.h), each named in the
// equation syntax (docs/data.md#equation-syntax: "u", "v*r", "abs(u)*u", "tau_x") so a fitted
// row of weights is an equation that can be written out.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace usvid {

struct NamedSignal {
  std::string name;
  Eigen::VectorXd values;
};

struct LibraryOptions {
  bool constant = true;
  bool products = true;   // x_i x_k
  bool abs_terms = true;  // |x_i| x_i
  // x_i u_j, u_j u_m (j <= m), |u_j| u_j: after the inputs, so the other columns keep their
  // order.
  bool input_products = false;
  // A rudder's force at its inflow speed: the rudder angle `delta` times |u| u, u n+ and n+ n+
  // (preprocessing/rudder_inflow.h), of the channels there are. After every other column.
  bool rudder_inflow = false;
};

struct RegressorLibrary {
  std::vector<std::string> names;
  Eigen::MatrixXd columns;  // rows: samples, one column per name
};

RegressorLibrary BuildLibrary(const std::vector<NamedSignal>& states,
                              const std::vector<NamedSignal>& inputs,
                              const LibraryOptions& options);

// Least-squares weights of target on the columns, and the fit's R^2 (1 - SSR / SST).
struct LinearFit {
  Eigen::VectorXd weights;
  double r2 = 0.0;
  double ssr = 0.0;
};
LinearFit FitLeastSquares(const Eigen::MatrixXd& columns, const Eigen::VectorXd& target);

}  // namespace usvid
