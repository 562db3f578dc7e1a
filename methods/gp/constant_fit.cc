#include "methods/gp/constant_fit.h"

#include <ceres/ceres.h>

#include <algorithm>
#include <cmath>

#include "core/expression.h"

namespace usvid::gp {
namespace {

// The constant nodes whose value is more than a scale factor of their term: some node between
// them and the term's root is not a product.
std::vector<int> TunableConstants(const Model& model) {
  const Tree& tree = model.tree;
  std::vector<int> parent(tree.size(), -1);
  for (int i = 0; i < static_cast<int>(tree.size()); ++i)
    for (int c : Children(tree, i)) parent[c] = i;
  std::vector<bool> is_root(tree.size(), false);
  for (int r : model.term_roots) is_root[r] = true;
  std::vector<int> out;
  for (int i = 0; i < static_cast<int>(tree.size()); ++i) {
    if (tree[i].op != Op::kConst || is_root[i]) continue;
    for (int a = parent[i]; a >= 0; a = parent[a]) {
      if (tree[a].op != Op::kMul) {
        out.push_back(i);
        break;
      }
      if (is_root[a]) break;
    }
  }
  return out;
}

// Residuals y_i - b - sum_t w_t term_t(x_i; c) over every row; parameters [c..., b, w...].
class TreeResidual {
 public:
  TreeResidual(const Model& model, std::vector<int> constants,
               const std::vector<const double*>& columns, const double* target, long rows)
      : tree_(model.tree),
        roots_(model.term_roots),
        constants_(std::move(constants)),
        columns_(columns),
        target_(target),
        rows_(rows) {}

  template <typename T>
  bool operator()(T const* const* parameters, T* residuals) const {
    using std::abs, std::cos, std::sin, std::tanh;
    const T* p = parameters[0];
    const size_t nc = constants_.size();
    std::vector<T> constant(tree_.size(), T(0.0));
    for (size_t i = 0; i < tree_.size(); ++i)
      if (tree_[i].op == Op::kConst) constant[i] = T(tree_[i].value);
    for (size_t k = 0; k < nc; ++k) constant[constants_[k]] = p[k];
    std::vector<T> v(tree_.size());
    for (long row = 0; row < rows_; ++row) {
      for (size_t i = 0; i < tree_.size(); ++i) {
        const Node& n = tree_[i];
        const T* a = nullptr;
        const T* b = nullptr;
        if (Arity(n.op) == 2) {
          b = &v[i - 1];
          a = &v[i - 1 - tree_[i - 1].length];
        } else if (Arity(n.op) == 1) {
          a = &v[i - 1];
        }
        switch (n.op) {
          case Op::kConst:
            v[i] = constant[i];
            break;
          case Op::kVar:
            v[i] = T(columns_[n.var][row]);
            break;
          case Op::kAdd:
            v[i] = *a + *b;
            break;
          case Op::kSub:
            v[i] = *a - *b;
            break;
          case Op::kMul:
            v[i] = *a * *b;
            break;
          case Op::kDiv:
            v[i] = ProtectedDivide(*a, *b);
            break;
          case Op::kAbs:
            v[i] = abs(*a);
            break;
          case Op::kTanh:
            v[i] = tanh(*a);
            break;
          case Op::kSin:
            v[i] = sin(*a);
            break;
          case Op::kCos:
            v[i] = cos(*a);
            break;
          case Op::kExp:
            v[i] = ProtectedExp(*a);
            break;
          case Op::kSqrt:
            v[i] = ProtectedSqrt(*a);
            break;
        }
      }
      T prediction = p[nc];
      for (size_t t = 0; t < roots_.size(); ++t) prediction += p[nc + 1 + t] * v[roots_[t]];
      residuals[row] = T(target_[row]) - prediction;
    }
    return true;
  }

 private:
  const Tree& tree_;
  const std::vector<int>& roots_;
  std::vector<int> constants_;
  const std::vector<const double*>& columns_;
  const double* target_;
  long rows_;
};

}  // namespace

bool HasTunableConstants(const Model& model) { return !TunableConstants(model).empty(); }

ConstantFitResult FitConstants(const Model& model, const std::vector<const double*>& columns,
                               const double* target, long rows, int iterations) {
  ConstantFitResult result;
  result.tree = model.tree;
  const std::vector<int> constants = TunableConstants(model);
  if (constants.empty() || iterations <= 0 || rows < 1 || model.term_roots.empty()) return result;
  std::vector<double> p;
  for (int c : constants) p.push_back(model.tree[c].value);
  p.push_back(model.bias);
  for (double w : model.weights) p.push_back(w);

  auto* cost = new ceres::DynamicAutoDiffCostFunction<TreeResidual, 8>(
      new TreeResidual(model, constants, columns, target, rows));
  cost->AddParameterBlock(static_cast<int>(p.size()));
  cost->SetNumResiduals(static_cast<int>(rows));
  ceres::Problem problem;
  problem.AddResidualBlock(cost, nullptr, p.data());
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = iterations;
  options.num_threads = 1;
  options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  result.initial_cost = summary.initial_cost;
  result.final_cost = summary.final_cost;
  result.iterations = static_cast<int>(summary.iterations.size());
  const bool finite = std::all_of(p.begin(), p.end(), [](double x) { return std::isfinite(x); });
  result.improved =
      finite && std::isfinite(summary.final_cost) && summary.final_cost < summary.initial_cost;
  if (result.improved)
    for (size_t k = 0; k < constants.size(); ++k) result.tree[constants[k]].value = p[k];
  return result;
}

}  // namespace usvid::gp
