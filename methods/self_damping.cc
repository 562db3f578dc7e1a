#include "methods/self_damping.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "core/expression.h"
#include "methods/straight_running.h"

namespace usvid {
namespace {

constexpr Eigen::Index kMaxRows = 20000;  // a long log's mean from evenly strided rows

// A state's equation and the data's channels of its variables, in the expression's order.
struct Equation {
  Expression f;
  std::vector<const Channel*> channels;
  int self = -1;  // the state among them; -1: the equation does not read it
};

// The state's equation when the data hold its state and every variable it reads.
std::optional<Equation> Resolve(const std::string& state, const std::string& text,
                                const Dataset& data) {
  if (!data.Has(state)) return std::nullopt;
  Equation e{Expression::Parse(text, "equations." + state), {}, -1};
  for (const std::string& name : e.f.Variables()) {
    const Channel* c = data.Find(name);
    if (c == nullptr) return std::nullopt;
    if (name == state) e.self = static_cast<int>(e.channels.size());
    e.channels.push_back(c);
  }
  return e;
}

double Rms(const Channel& x) {
  return std::sqrt(x.values().array().isNaN().select(0.0, x.values().array()).square().mean());
}

// d f / d vars[self] at `vars`, by central differences of step 1e-6 (|x| + rms).
double Slope(const Expression& f, std::vector<double> vars, size_t self, double rms) {
  const double x0 = vars[self];
  const double h = 1e-6 * (std::abs(x0) + rms + 1e-12);
  vars[self] = x0 + h;
  const double up = f.Evaluate(vars);
  vars[self] = x0 - h;
  return (up - f.Evaluate(vars)) / (2.0 * h);
}

}  // namespace

std::map<std::string, double> SelfDamping(const EquationList& equations, const Dataset& data) {
  std::map<std::string, double> out;
  for (const auto& [state, text] : equations) {
    const std::optional<Equation> e = Resolve(state, text, data);
    if (!e) continue;
    if (e->self < 0) {  // the equation does not read its state: no damping at all
      out[state] = 0.0;
      continue;
    }
    const size_t self = static_cast<size_t>(e->self);
    const double rms = Rms(*e->channels[self]);
    std::vector<double> vars(e->channels.size());
    double sum = 0.0;
    long rows = 0;
    const Eigen::Index stride = std::max<Eigen::Index>(1, data.rows() / kMaxRows);
    for (Eigen::Index i = 0; i < data.rows(); i += stride) {
      bool sampled = true;
      for (size_t k = 0; k < e->channels.size() && sampled; ++k) {
        sampled = e->channels[k]->IsSampled(i);
        vars[k] = e->channels[k]->Value(i);
      }
      if (!sampled) continue;
      const double d = Slope(e->f, vars, self, rms);
      if (!std::isfinite(d)) continue;
      sum += d;
      ++rows;
    }
    if (rows > 0) out[state] = sum / static_cast<double>(rows);
  }
  return out;
}

std::map<std::string, double> StraightRunningDamping(const EquationList& equations,
                                                     const Dataset& data) {
  std::map<std::string, double> out;
  for (const auto& [state, text] : equations) {
    const std::optional<Equation> e = Resolve(state, text, data);
    if (!e) continue;
    if (e->self < 0) {
      out[state] = 0.0;
      continue;
    }
    std::vector<ChannelLevel> levels;
    for (const Channel* c : e->channels) {
      std::vector<double> samples;
      for (Eigen::Index i = 0; i < data.rows(); ++i)
        if (c->IsSampled(i)) samples.push_back(c->Value(i));
      levels.push_back(LevelOf(std::move(samples)));
    }
    const size_t self = static_cast<size_t>(e->self);
    const std::vector<std::vector<double>> points =
        StraightRunningPoints(e->f.Variables(), levels, self);
    double sum = 0.0;
    for (const std::vector<double>& p : points) sum += Slope(e->f, p, self, levels[self].rms);
    const double d = sum / static_cast<double>(points.size());
    if (std::isfinite(d)) out[state] = d;
  }
  return out;
}

}  // namespace usvid
