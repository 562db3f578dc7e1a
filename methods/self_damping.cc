#include "methods/self_damping.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/expression.h"

namespace usvid {
namespace {

constexpr Eigen::Index kMaxRows = 20000;  // a long log's mean from evenly strided rows

}  // namespace

std::map<std::string, double> SelfDamping(const nlohmann::json& equations, const Dataset& data) {
  std::map<std::string, double> out;
  for (const auto& [state, text] : equations.items()) {
    if (!text.is_string() || !data.Has(state)) continue;
    const Expression f = Expression::Parse(text.get<std::string>(), "equations." + state);
    const std::vector<std::string>& names = f.Variables();
    std::vector<const Channel*> channels;
    int self = -1;
    for (const std::string& name : names) {
      const Channel* c = data.Find(name);
      if (c == nullptr) break;
      if (name == state) self = static_cast<int>(channels.size());
      channels.push_back(c);
    }
    if (channels.size() != names.size()) continue;
    if (self < 0) {  // the equation does not read its state: no damping at all
      out[state] = 0.0;
      continue;
    }
    const Channel& x = *channels[static_cast<size_t>(self)];
    const double rms =
        std::sqrt(x.values().array().isNaN().select(0.0, x.values().array()).square().mean());
    std::vector<double> vars(names.size());
    double sum = 0.0;
    long rows = 0;
    const Eigen::Index stride = std::max<Eigen::Index>(1, data.rows() / kMaxRows);
    for (Eigen::Index i = 0; i < data.rows(); i += stride) {
      bool sampled = true;
      for (size_t k = 0; k < channels.size() && sampled; ++k) {
        sampled = channels[k]->IsSampled(i);
        vars[k] = channels[k]->Value(i);
      }
      if (!sampled) continue;
      const double x0 = vars[static_cast<size_t>(self)];
      const double h = 1e-6 * (std::abs(x0) + rms + 1e-12);
      vars[static_cast<size_t>(self)] = x0 + h;
      const double up = f.Evaluate(vars);
      vars[static_cast<size_t>(self)] = x0 - h;
      const double down = f.Evaluate(vars);
      const double d = (up - down) / (2.0 * h);
      if (!std::isfinite(d)) continue;
      sum += d;
      ++rows;
    }
    if (rows > 0) out[state] = sum / static_cast<double>(rows);
  }
  return out;
}

}  // namespace usvid
