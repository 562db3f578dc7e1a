#include "methods/gp/model_selection.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/error.h"
#include "methods/gp/interpreter.h"

namespace usvid::gp {
namespace {

constexpr double kDivergedPenalty = 100.0;  // variances per sample left after leaving the bounds

// Integrates segments side by side: segment j starts at row starts[j] and runs `steps` samples.
class SegmentSimulator {
 public:
  SegmentSimulator(const SelectionData& data, const std::vector<int>& state_vars)
      : data_(data), state_vars_(state_vars) {
    is_state_.assign(data.names.size(), -1);
    for (size_t s = 0; s < state_vars.size(); ++s) is_state_[state_vars[s]] = static_cast<int>(s);
    for (int v : state_vars) {
      const Eigen::VectorXd& x = data.variables[v];
      const Eigen::VectorXd tail = x.tail(x.size() - data.validation_begin);
      const double mean = tail.mean();
      variance_.push_back(std::max((tail.array() - mean).square().mean(), 1e-12));
      bound_.push_back(std::max(10.0 * x.cwiseAbs().maxCoeff(), 1e-6));
    }
  }

  // The mean over segments, steps and states of the squared error over the state's variance;
  // `diverged` says whether any segment left the bounds.
  double Error(const std::vector<const Model*>& models, const std::vector<long>& starts,
               long steps, bool& diverged) const {
    const int ns = static_cast<int>(state_vars_.size());
    const int nv = static_cast<int>(data_.names.size());
    diverged = false;
    double total = 0.0;
    for (size_t first = 0; first < starts.size(); first += Interpreter<double>::kBatch) {
      const int count = static_cast<int>(
          std::min<size_t>(Interpreter<double>::kBatch, starts.size() - first));
      std::vector<std::vector<double>> cols(nv, std::vector<double>(count));
      std::vector<const double*> pointers;
      for (const auto& c : cols) pointers.push_back(c.data());
      Interpreter<double> interp(pointers);
      Eigen::ArrayXXd x(ns, count), k1(ns, count), k2(ns, count), k3(ns, count), k4(ns, count);
      std::vector<bool> active(count, true);
      for (int j = 0; j < count; ++j)
        for (int s = 0; s < ns; ++s) x(s, j) = data_.variables[state_vars_[s]](starts[first + j]);
      auto derivative = [&](long k, const Eigen::ArrayXXd& state, Eigen::ArrayXXd& dx) {
        for (int v = 0; v < nv; ++v)
          for (int j = 0; j < count; ++j)
            cols[v][j] = is_state_[v] >= 0 ? state(is_state_[v], j)
                                           : data_.variables[v](starts[first + j] + k);
        for (int s = 0; s < ns; ++s) {
          const Model& m = *models[s];
          interp.Evaluate(m.tree, 0, count);
          for (int j = 0; j < count; ++j) dx(s, j) = m.bias;
          for (size_t t = 0; t < m.term_roots.size(); ++t) {
            const double* term = interp.Column(m.term_roots[t]);
            for (int j = 0; j < count; ++j) dx(s, j) += m.weights[t] * term[j];
          }
        }
      };
      for (long k = 0; k < steps; ++k) {
        Eigen::ArrayXd h(count);
        for (int j = 0; j < count; ++j)
          h(j) = data_.t(starts[first + j] + k + 1) - data_.t(starts[first + j] + k);
        const Eigen::ArrayXXd hh = h.transpose().replicate(ns, 1);
        derivative(k, x, k1);
        derivative(k, x + 0.5 * hh * k1, k2);
        derivative(k, x + 0.5 * hh * k2, k3);
        derivative(k, x + hh * k3, k4);
        x += hh / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
        for (int j = 0; j < count; ++j) {
          const long row = starts[first + j] + k + 1;
          if (!active[j]) {
            total += kDivergedPenalty * ns;
          } else {
            bool out = false;
            for (int s = 0; s < ns; ++s) out |= !(std::abs(x(s, j)) <= bound_[s]);
            if (out) {
              active[j] = false;
              diverged = true;
              total += kDivergedPenalty * ns;
            } else {
              for (int s = 0; s < ns; ++s) {
                const double e = x(s, j) - data_.variables[state_vars_[s]](row);
                total += e * e / variance_[s];
              }
            }
          }
          if (!active[j])  // keep the frozen segment finite
            for (int s = 0; s < ns; ++s) x(s, j) = data_.variables[state_vars_[s]](row);
        }
      }
    }
    return total / (static_cast<double>(starts.size()) * static_cast<double>(steps) * ns);
  }

 private:
  const SelectionData& data_;
  std::vector<int> state_vars_;
  std::vector<int> is_state_;
  std::vector<double> variance_, bound_;
};

}  // namespace

Selection SelectModels(const SelectionData& data, const std::vector<StateCandidates>& states) {
  const long rows = data.t.size();
  std::vector<int> state_vars;
  for (const StateCandidates& s : states) {
    const auto it = std::find(data.names.begin(), data.names.end(), s.state);
    if (it == data.names.end())
      throw InputError("gp model selection: state '" + s.state + "' is not a variable");
    if (s.models.empty()) throw InputError("gp model selection: no candidates for " + s.state);
    state_vars.push_back(static_cast<int>(it - data.names.begin()));
  }
  if (data.validation_begin < 0 || rows - data.validation_begin < 2)
    throw InputError("gp model selection: the validation part has fewer than 2 samples");
  const SegmentSimulator sim(data, state_vars);

  // Segments of the horizon over the validation rows (one shorter segment when it is short).
  const double dt = (data.t(rows - 1) - data.t(0)) / static_cast<double>(rows - 1);
  const long span = rows - 1 - data.validation_begin;
  const long steps = std::clamp<long>(std::lround(data.horizon_s / dt), 1, span);
  std::vector<long> starts;
  for (long s = data.validation_begin; s + steps <= rows - 1; s += steps) starts.push_back(s);

  Selection out;
  std::map<std::vector<size_t>, double> scored;
  auto score = [&](const std::vector<size_t>& combo) {
    if (const auto it = scored.find(combo); it != scored.end()) return it->second;
    std::vector<const Model*> models;
    for (size_t s = 0; s < states.size(); ++s) models.push_back(&states[s].models[combo[s]]);
    bool diverged = false;
    const double e = sim.Error(models, starts, steps, diverged);
    ++out.combinations_scored;
    return scored[combo] = std::isfinite(e) ? e : INFINITY;
  };
  auto size_of = [&](const std::vector<size_t>& combo) {
    size_t n = 0;
    for (size_t s = 0; s < states.size(); ++s) n += states[s].models[combo[s]].Size();
    return n;
  };

  std::vector<size_t> chosen(states.size(), 0);
  out.last_pass.resize(states.size());
  for (int pass = 0; pass < 2; ++pass) {
    for (size_t s = 0; s < states.size(); ++s) {
      std::vector<size_t> combo = chosen;
      out.last_pass[s].clear();
      for (size_t c = 0; c < states[s].models.size(); ++c) {
        combo[s] = c;
        const double e = score(combo);
        out.last_pass[s].push_back({c, e});
        std::vector<size_t> current = chosen;
        const double best = score(current);
        if (e < best || (e == best && size_of(combo) < size_of(current))) chosen[s] = c;
      }
    }
  }

  // The best combination scored that free-runs the training record within the bounds.
  std::vector<std::pair<double, std::vector<size_t>>> ranked;
  for (const auto& [combo, e] : scored) ranked.emplace_back(e, combo);
  std::stable_sort(ranked.begin(), ranked.end(), [&](const auto& a, const auto& b) {
    return a.first < b.first || (a.first == b.first && size_of(a.second) < size_of(b.second));
  });
  out.chosen = ranked.front().second;
  out.score = ranked.front().first;
  out.free_run_diverged = true;
  for (size_t i = 0; i < ranked.size() && i < 20; ++i) {
    std::vector<const Model*> models;
    for (size_t s = 0; s < states.size(); ++s)
      models.push_back(&states[s].models[ranked[i].second[s]]);
    bool diverged = false;
    sim.Error(models, {0}, rows - 1, diverged);
    if (!diverged) {
      out.chosen = ranked[i].second;
      out.score = ranked[i].first;
      out.free_run_diverged = false;
      break;
    }
    ++out.rejected_for_divergence;
  }
  return out;
}

}  // namespace usvid::gp
