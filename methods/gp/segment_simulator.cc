#include "methods/gp/segment_simulator.h"

#include <algorithm>
#include <cmath>
#include <span>

#include "core/stretches.h"
#include "methods/gp/interpreter.h"

namespace usvid::gp {

SegmentSimulator::SegmentSimulator(const SelectionData& data, const std::vector<int>& state_vars)
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

std::vector<long> SegmentSimulator::Starts(const Eigen::VectorXd& t, long first, long end,
                                           long steps) {
  std::vector<long> starts;
  for (const Stretch& st : Stretches(t, kGridGapFactor)) {
    const long stop = std::min<long>(end, st.end);
    for (long s = std::max<long>(first, st.first); s + steps < stop; s += steps)
      starts.push_back(s);
  }
  return starts;
}

double SegmentSimulator::FreeRunError(const std::vector<const Model*>& models,
                                      bool& diverged) const {
  diverged = false;
  double total = 0.0;
  long steps = 0;
  for (const Stretch& st : Stretches(data_.t, kGridGapFactor)) {
    if (st.rows() < 2) continue;
    bool out = false;
    total += Error(models, {static_cast<long>(st.first)}, st.rows() - 1, out) *
             static_cast<double>(st.rows() - 1);
    steps += st.rows() - 1;
    diverged |= out;
  }
  return steps > 0 ? total / static_cast<double>(steps) : 0.0;
}

// Which variables the models read: those their trees name, and the arguments of each derived
// column they read (a derived column may read one before it, so in reverse order).
std::vector<bool> SegmentSimulator::Read(const std::vector<const Model*>& models) const {
  std::vector<bool> read(data_.names.size(), false);
  for (const Model* m : models)
    for (const Node& node : m->tree)
      if (node.op == Op::kVar) read[node.var] = true;
  for (auto d = data_.derived.rbegin(); d != data_.derived.rend(); ++d)
    if (read[d->index])
      for (const int a : d->arguments) read[a] = true;
  return read;
}

void SegmentSimulator::FillColumns(const std::vector<bool>& read, const Eigen::ArrayXXd& state,
                                   const long* starts, long k,
                                   std::vector<std::vector<double>>& cols,
                                   std::vector<const double*>& args) const {
  const int count = static_cast<int>(state.cols());
  for (size_t v = 0; v < cols.size(); ++v)
    if (read[v])
      for (int j = 0; j < count; ++j)
        cols[v][j] = is_state_[v] >= 0 ? state(is_state_[v], j) : data_.variables[v](starts[j] + k);
  for (const DerivedColumn& d : data_.derived) {
    if (!read[d.index]) continue;
    for (size_t a = 0; a < d.arguments.size(); ++a) args[a] = cols[d.arguments[a]].data();
    d.expression.EvaluateColumns(std::span<const double* const>(args.data(), d.arguments.size()),
                                 count, cols[d.index].data());
  }
}

double SegmentSimulator::Error(const std::vector<const Model*>& models,
                               const std::vector<long>& starts, long steps, bool& diverged,
                               std::vector<double>* per_segment,
                               std::vector<double>* residuals) const {
  const int ns = static_cast<int>(state_vars_.size());
  const int nv = static_cast<int>(data_.names.size());
  // A column no model reads is neither filled nor derived: on odin-hs the regime features (Fn
  // and its hinges, each a square root) took over a third of this function when derived at
  // every stage whether read or not (docs/performance.md, item 9).
  const std::vector<bool> read = Read(models);
  diverged = false;
  std::vector<double> segment(starts.size(), 0.0);
  if (residuals) residuals->assign(starts.size() * steps * ns, 0.0);
  for (size_t first = 0; first < starts.size(); first += Interpreter<double>::kBatch) {
    const int count =
        static_cast<int>(std::min<size_t>(Interpreter<double>::kBatch, starts.size() - first));
    std::vector<std::vector<double>> cols(nv, std::vector<double>(count));
    std::vector<const double*> pointers;
    for (const auto& c : cols) pointers.push_back(c.data());
    Interpreter<double> interp(pointers);
    std::vector<const double*> args(nv);  // FillColumns' buffer: a derived column's arguments
    Eigen::ArrayXXd x(ns, count), k1(ns, count), k2(ns, count), k3(ns, count), k4(ns, count);
    std::vector<bool> active(count, true);
    for (int j = 0; j < count; ++j)
      for (int s = 0; s < ns; ++s) x(s, j) = data_.variables[state_vars_[s]](starts[first + j]);
    auto derivative = [&](long k, const Eigen::ArrayXXd& state, Eigen::ArrayXXd& dx) {
      FillColumns(read, state, &starts[first], k, cols, args);
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
        hh.col(j).setConstant(data_.t(starts[first + j] + k + 1) - data_.t(starts[first + j] + k));
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
              if (residuals)
                (*residuals)[((first + j) * steps + k) * ns + s] = e / std::sqrt(variance_[s]);
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

}  // namespace usvid::gp
