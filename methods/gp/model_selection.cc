#include "methods/gp/model_selection.h"

#include <algorithm>
#include <cmath>
#include <span>

#include "core/error.h"
#include "methods/gp/interpreter.h"

namespace usvid::gp {
namespace {

constexpr double kDivergedPenalty = 100.0;  // variances per sample left after leaving the bounds

// Integrates segments side by side: segment j starts at row starts[j] and runs `steps` samples.
class SegmentSimulator {
 public:
  // `state_vars`: the variables integrated; the others are read from the data.
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
  // `diverged` says whether any segment left the bounds. `per_segment` (when given) receives
  // each segment's mean.
  double Error(const std::vector<const Model*>& models, const std::vector<long>& starts, long steps,
               bool& diverged, std::vector<double>* per_segment = nullptr) const {
    const int ns = static_cast<int>(state_vars_.size());
    const int nv = static_cast<int>(data_.names.size());
    diverged = false;
    std::vector<double> segment(starts.size(), 0.0);
    for (size_t first = 0; first < starts.size(); first += Interpreter<double>::kBatch) {
      const int count =
          static_cast<int>(std::min<size_t>(Interpreter<double>::kBatch, starts.size() - first));
      std::vector<std::vector<double>> cols(nv, std::vector<double>(count));
      std::vector<const double*> pointers;
      for (const auto& c : cols) pointers.push_back(c.data());
      Interpreter<double> interp(pointers);
      std::vector<double> args(data_.names.size());  // a derived column's arguments at one row
      Eigen::ArrayXXd x(ns, count), k1(ns, count), k2(ns, count), k3(ns, count), k4(ns, count);
      std::vector<bool> active(count, true);
      for (int j = 0; j < count; ++j)
        for (int s = 0; s < ns; ++s) x(s, j) = data_.variables[state_vars_[s]](starts[first + j]);
      auto derivative = [&](long k, const Eigen::ArrayXXd& state, Eigen::ArrayXXd& dx) {
        for (int v = 0; v < nv; ++v)
          for (int j = 0; j < count; ++j)
            cols[v][j] = is_state_[v] >= 0 ? state(is_state_[v], j)
                                           : data_.variables[v](starts[first + j] + k);
        for (const DerivedColumn& d : data_.derived)
          for (int j = 0; j < count; ++j) {
            for (size_t a = 0; a < d.arguments.size(); ++a) args[a] = cols[d.arguments[a]][j];
            cols[d.index][j] =
                d.expression.Evaluate(std::span<const double>(args.data(), d.arguments.size()));
          }
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
      Eigen::ArrayXXd hh(ns, count);  // each segment's step, for every state
      for (long k = 0; k < steps; ++k) {
        for (int j = 0; j < count; ++j)
          hh.col(j).setConstant(data_.t(starts[first + j] + k + 1) -
                                data_.t(starts[first + j] + k));
        derivative(k, x, k1);
        derivative(k, x + 0.5 * hh * k1, k2);
        derivative(k, x + 0.5 * hh * k2, k3);
        derivative(k, x + hh * k3, k4);
        x += hh / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
        for (int j = 0; j < count; ++j) {
          const long row = starts[first + j] + k + 1;
          if (!active[j]) {
            segment[first + j] += kDivergedPenalty * ns;
          } else {
            bool out = false;
            for (int s = 0; s < ns; ++s) out |= !(std::abs(x(s, j)) <= bound_[s]);
            if (out) {
              active[j] = false;
              diverged = true;
              segment[first + j] += kDivergedPenalty * ns;
            } else {
              for (int s = 0; s < ns; ++s) {
                const double e = x(s, j) - data_.variables[state_vars_[s]](row);
                segment[first + j] += e * e / variance_[s];
              }
            }
          }
          if (!active[j])  // keep the frozen segment finite
            for (int s = 0; s < ns; ++s) x(s, j) = data_.variables[state_vars_[s]](row);
        }
      }
    }
    double total = 0.0;
    for (double& e : segment) {
      e /= static_cast<double>(steps) * ns;
      total += e;
    }
    if (per_segment) *per_segment = segment;
    return total / static_cast<double>(starts.size());
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

  // Segments of the horizon over the validation rows (one shorter segment when it is short).
  const double dt = (data.t(rows - 1) - data.t(0)) / static_cast<double>(rows - 1);
  const long span = rows - 1 - data.validation_begin;
  const long steps = std::clamp<long>(std::lround(data.horizon_s / dt), 1, span);
  std::vector<long> starts;
  for (long s = data.validation_begin; s + steps <= rows - 1; s += steps) starts.push_back(s);

  Selection out;
  out.candidate_scores.resize(states.size());
  // Each state's candidates on their own: that state integrated, the others as measured, so a
  // wrong equation of one state cannot make a wrong one of another look right.
  std::vector<std::vector<size_t>> ranked(states.size());
  for (size_t s = 0; s < states.size(); ++s) {
    const std::vector<Model>& models = states[s].models;
    const SegmentSimulator sim(data, {state_vars[s]});
    std::vector<std::vector<double>> segments(models.size());
    for (size_t c = 0; c < models.size(); ++c) {
      bool diverged = false;
      const double e = sim.Error({&models[c]}, starts, steps, diverged, &segments[c]);
      out.candidate_scores[s].push_back({c, std::isfinite(e) ? e : INFINITY});
      ++out.candidates_scored;
    }
    // The one-standard-error rule: the smallest candidate within one standard error (over
    // segments) of the smallest error comes first, then the rest by error.
    size_t best = 0;
    for (size_t c = 1; c < models.size(); ++c)
      if (out.candidate_scores[s][c].score < out.candidate_scores[s][best].score) best = c;
    double se = 0.0;
    const std::vector<double>& e = segments[best];
    if (e.size() > 1 && std::isfinite(out.candidate_scores[s][best].score)) {
      const double mean = out.candidate_scores[s][best].score;
      for (double x : e) se += (x - mean) * (x - mean);
      se = std::sqrt(se / static_cast<double>(e.size() - 1) / static_cast<double>(e.size()));
    }
    size_t pick = best;
    for (size_t c = 0; c < models.size(); ++c)
      if (out.candidate_scores[s][c].score <= out.candidate_scores[s][best].score + se &&
          (models[c].Size() < models[pick].Size() ||
           (models[c].Size() == models[pick].Size() &&
            out.candidate_scores[s][c].score < out.candidate_scores[s][pick].score)))
        pick = c;
    std::vector<ScoredCandidate> order = out.candidate_scores[s];
    std::stable_sort(
        order.begin(), order.end(), [&](const ScoredCandidate& a, const ScoredCandidate& b) {
          if ((a.index == pick) != (b.index == pick)) return a.index == pick;
          return a.score < b.score ||
                 (a.score == b.score && models[a.index].Size() < models[b.index].Size());
        });
    for (const ScoredCandidate& c : order) ranked[s].push_back(c.index);
    out.standard_errors.push_back(se);
  }

  // The best of each, then one state at a time moved to its next best, until the whole model
  // free-runs the training record within the bounds.
  const SegmentSimulator joint(data, state_vars);
  std::vector<std::vector<size_t>> tries = {std::vector<size_t>(states.size(), 0)};
  for (size_t k = 1; tries.size() < 20; ++k) {
    bool any = false;
    for (size_t s = 0; s < states.size() && tries.size() < 20; ++s)
      if (k < ranked[s].size()) {
        std::vector<size_t> rank(states.size(), 0);
        rank[s] = k;
        tries.push_back(rank);
        any = true;
      }
    if (!any) break;
  }
  auto combination = [&](const std::vector<size_t>& rank) {
    std::vector<size_t> combo;
    for (size_t s = 0; s < states.size(); ++s) combo.push_back(ranked[s][rank[s]]);
    return combo;
  };
  out.chosen = combination(tries[0]);
  out.free_run_diverged = true;
  for (const std::vector<size_t>& rank : tries) {
    const std::vector<size_t> combo = combination(rank);
    std::vector<const Model*> models;
    for (size_t s = 0; s < states.size(); ++s) models.push_back(&states[s].models[combo[s]]);
    bool diverged = false;
    joint.Error(models, {0}, rows - 1, diverged);
    if (!diverged) {
      out.chosen = combo;
      out.free_run_diverged = false;
      break;
    }
    ++out.rejected_for_divergence;
  }
  for (size_t s = 0; s < states.size(); ++s)
    out.scores.push_back(out.candidate_scores[s][out.chosen[s]].score);
  return out;
}

}  // namespace usvid::gp
