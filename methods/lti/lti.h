// A linear time-invariant model, the baseline every nonlinear method must beat: each state's
// derivative a linear combination of the variables and inputs,
//   x_i' = c_i + sum_j a_ij x_j + sum_k b_ik u_k,
// fitted by ridge regression on the preprocessed derivatives (equation error):
//   w = argmin |y - A w|^2 + ridge sum_j |a_j|^2 w_j^2,
// the penalty relative to each column's energy |a_j|^2, so that `ridge` is dimensionless and
// the constant is never penalised. ridge 0 is ordinary least squares (column-pivoted QR, so a
// column that repeats another gets weight 0 instead of a blow-up).
//
// The equations are in the equation syntax of docs/data.md#equation-syntax, coefficients
// written to round-trip exactly; usvid evaluate integrates them as any model.json's.
// Throws InputError for a missing or non-finite channel, fewer rows than terms, or a negative
// or non-finite ridge.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "preprocessing/pipeline.h"

namespace usvid::lti {

// The name --method and suites give it (methods/method_list.h registers it).
inline constexpr std::string_view kMethodName = "lti";

struct LtiOptions {
  double ridge = 0.0;    // relative to each column's energy
  bool constant = true;  // a constant term in each equation
};

struct LtiIdentification {
  nlohmann::json equations = nlohmann::json::object();   // state -> its derivative
  nlohmann::json parameters = nlohmann::json::object();  // "<state>.<term>" -> coefficient
  nlohmann::json details = nlohmann::json::object();     // per state: terms, r2_train
};

// One equation per state (target "<state>_dot" in prepared.data) in `variables` and `inputs`.
LtiIdentification IdentifyLti(const PreparedData& prepared, const std::vector<std::string>& states,
                              const std::vector<std::string>& variables,
                              const std::vector<std::string>& inputs, const LtiOptions& options);

}  // namespace usvid::lti
