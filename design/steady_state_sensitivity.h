// How a vessel's steady state moves with its parameters. At a held input tau, the dynamic states
// x (every state but positions and heading) settle where f(x, tau, p) = 0, f their derivatives;
// by the implicit function theorem
//     dx_ss/dp = -(df/dx)^-1 df/dp,
// with both Jacobians from Jets through the vessel's templated Derivative. Units: the states' per
// the parameters' units. The kinematic states are held at the given values (they do not enter a
// hull's forces without a current). Returns an empty matrix where df/dx is singular (no unique
// steady state).
#pragma once

#include <Eigen/Core>
#include <Eigen/LU>
#include <array>
#include <ceres/jet.h>
#include <vector>

#include "simulators/vessel.h"

namespace usvid::design {

template <Vessel V>
constexpr int DynamicStateCount() {
  int n = 0;
  for (std::string_view s : V::kStateNames) n += IsPositionOrHeading(s) ? 0 : 1;
  return n;
}

// The Jacobians of the dynamic states' derivatives f: rows the dynamic states in the vessel's
// order, fx by those states, fp by the parameters.
struct DerivativeJacobians {
  Eigen::MatrixXd fx, fp;
};

template <Vessel V>
DerivativeJacobians DerivativeJacobiansAt(const std::vector<double>& x,
                                          const std::vector<double>& tau,
                                          const std::vector<double>& p) {
  constexpr int kDyn = DynamicStateCount<V>();
  using J = ceres::Jet<double, kDyn + V::kParams>;
  std::array<int, kDyn> dyn{};
  for (int i = 0, k = 0; i < V::kStates; ++i)
    if (!IsPositionOrHeading(V::kStateNames[i])) dyn[k++] = i;
  std::array<J, V::kStates> xj, dx;
  std::array<J, V::kInputs> uj;
  std::array<J, V::kParams> pj;
  for (int i = 0; i < V::kStates; ++i) xj[i] = J(x[i]);
  for (int k = 0; k < kDyn; ++k) xj[dyn[k]] = J(x[dyn[k]], k);
  for (int i = 0; i < V::kInputs; ++i) uj[i] = J(tau[i]);
  for (int j = 0; j < V::kParams; ++j) pj[j] = J(p[j], kDyn + j);
  V::template Derivative<J>(xj.data(), uj.data(), pj.data(), Environment<J>{}, dx.data());
  DerivativeJacobians d{Eigen::MatrixXd(kDyn, kDyn), Eigen::MatrixXd(kDyn, V::kParams)};
  for (int k = 0; k < kDyn; ++k) {
    d.fx.row(k) = dx[dyn[k]].v.head(kDyn).transpose();
    d.fp.row(k) = dx[dyn[k]].v.tail(V::kParams).transpose();
  }
  return d;
}

// dx_ss/dp: rows the dynamic states, columns the parameters; x, tau and p in the vessel's order
// and units.
template <Vessel V>
Eigen::MatrixXd SteadyStateSensitivity(const std::vector<double>& x, const std::vector<double>& tau,
                                       const std::vector<double>& p) {
  const DerivativeJacobians d = DerivativeJacobiansAt<V>(x, tau, p);
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(d.fx);
  if (!lu.isInvertible()) return {};
  return -lu.solve(d.fp);
}

}  // namespace usvid::design
