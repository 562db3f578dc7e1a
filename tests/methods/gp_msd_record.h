// GP test fixtures shared by the model selection and simulation refit tests: linear models of
// variables by index, and the mass-spring-damper x' = v, v' = -0.2 x - c v + 0.1 f sampled at
// 20 Hz.
#pragma once

#include <climits>
#include <cmath>
#include <utility>
#include <vector>

#include "methods/gp/ols.h"
#include "methods/gp/segment_simulator.h"

namespace usvid::gp::testing {

// bias + sum w_k * variable_k, variables by index.
inline Model Linear(const std::vector<std::pair<int, double>>& terms, double bias = 0.0) {
  Model m;
  for (size_t k = 0; k < terms.size(); ++k) {
    m.tree.push_back({Op::kVar, static_cast<uint16_t>(terms[k].first), 1, 0.0});
    if (k > 0) m.tree.push_back({Op::kAdd, 0, 1, 0.0});
    m.weights.push_back(terms[k].second);
  }
  UpdateLengths(m.tree);
  m.term_roots = SplitTerms(m.tree);
  m.bias = bias;
  return m;
}

// Variables x, v, f over `rows` samples; the damping c is 0.1 before row `change` and
// `damping_after` from it. The force f is held within each sample, the states integrated by
// Euler steps of 1 ms. validation_begin 0, horizon 10 s.
inline SelectionData MsdRecord(int rows, int change = INT_MAX, double damping_after = 0.1) {
  SelectionData d;
  d.names = {"x", "v", "f"};
  d.t.resize(rows);
  Eigen::VectorXd x(rows), v(rows), f(rows);
  double xs = 0.0, vs = 0.0;
  for (int i = 0; i < rows; ++i) {
    d.t(i) = 0.05 * i;
    f(i) = ((i / 200) % 3 - 1) * 2.0 + std::sin(0.013 * i);
    x(i) = xs;
    v(i) = vs;
    const double c = i < change ? 0.1 : damping_after;
    for (int k = 0; k < 50; ++k) {
      const double a = -0.2 * xs - c * vs + 0.1 * f(i);
      xs += 0.001 * vs;
      vs += 0.001 * a;
    }
  }
  d.variables = {x, v, f};
  return d;
}

}  // namespace usvid::gp::testing
