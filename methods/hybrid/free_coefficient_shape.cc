#include "methods/hybrid/free_coefficient_shape.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/expression.h"
#include "methods/refit/refit.h"

namespace usvid::hybrid {
namespace {

// |a . b| / (|a| |b|) over the rows where both are finite; 0 when either is zero there.
double AbsCosine(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  double ab = 0.0, aa = 0.0, bb = 0.0;
  for (Eigen::Index k = 0; k < a.size(); ++k) {
    if (!std::isfinite(a(k)) || !std::isfinite(b(k))) continue;
    ab += a(k) * b(k);
    aa += a(k) * a(k);
    bb += b(k) * b(k);
  }
  return aa > 0.0 && bb > 0.0 ? std::min(1.0, std::abs(ab) / std::sqrt(aa * bb)) : 0.0;
}

}  // namespace

std::vector<CoefficientShape> ClosestFreeCoefficient(const VesselRef& vessel,
                                                     const Dataset& prepared,
                                                     const std::vector<std::string>& names,
                                                     const std::vector<double>& params,
                                                     const std::vector<std::string>& free,
                                                     const std::vector<TermProposal>& proposals) {
  // df_s/dp for each free parameter, by central differences of the derivative residual
  // (d_s = s_dot - f_s, so d(p - h) - d(p + h) = 2 h df_s/dp).
  std::map<std::string, std::map<std::string, Eigen::VectorXd>> slope;  // [parameter][state]
  for (const std::string& p : free) {
    const auto at = std::find(names.begin(), names.end(), p);
    if (at == names.end()) continue;
    const size_t i = static_cast<size_t>(at - names.begin());
    const double h = 1e-4 * std::max(std::abs(params[i]), 1e-3);
    std::vector<double> up = params, down = params;
    up[i] += h;
    down[i] -= h;
    const auto d_up = DerivativeResidual(vessel, prepared, up);
    const auto d_down = DerivativeResidual(vessel, prepared, down);
    for (const auto& [state, column] : d_down) slope[p][state] = column - d_up.at(state);
  }
  std::vector<CoefficientShape> out;
  for (const TermProposal& proposal : proposals) {
    const Eigen::VectorXd term = Expression::Parse(proposal.term.term).Evaluate(prepared);
    CoefficientShape best;
    for (const auto& [p, by_state] : slope) {
      const auto column = by_state.find(proposal.term.state);
      if (column == by_state.end()) continue;
      const double c = AbsCosine(term, column->second);
      if (c > best.cosine) best = {p, c};
    }
    out.push_back(best);
  }
  return out;
}

}  // namespace usvid::hybrid
