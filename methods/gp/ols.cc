#include "methods/gp/ols.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>

namespace usvid::gp {
namespace {

void CollectTerms(const Tree& tree, int i, std::vector<int>& terms) {
  const Op op = tree[i].op;
  if (op == Op::kAdd || op == Op::kSub) {
    const std::vector<int> c = Children(tree, i);
    CollectTerms(tree, c[0], terms);
    CollectTerms(tree, c[1], terms);  // a minus sign is absorbed by the term's weight
  } else {
    terms.push_back(i);
  }
}

}  // namespace

std::vector<int> SplitTerms(const Tree& tree) {
  std::vector<int> terms;
  if (!tree.empty()) CollectTerms(tree, static_cast<int>(tree.size()) - 1, terms);
  return terms;
}

void NormalEquations::Add(const Eigen::Ref<const Eigen::MatrixXd>& x,
                          const Eigen::Ref<const Eigen::VectorXd>& y) {
  const Eigen::Index k = x.cols();
  gram(0, 0) += static_cast<double>(x.rows());
  gram.block(1, 0, k, 1) += x.colwise().sum().transpose();
  gram.block(1, 1, k, k).selfadjointView<Eigen::Lower>().rankUpdate(x.transpose());
  xty(0) += y.sum();
  xty.tail(k) += x.transpose() * y;
  yty += y.squaredNorm();
  rows += x.rows();
}

NormalEquations& NormalEquations::operator+=(const NormalEquations& other) {
  gram += other.gram;
  xty += other.xty;
  yty += other.yty;
  rows += other.rows;
  return *this;
}

bool SolveColumns(const Eigen::MatrixXd& gram, const Eigen::VectorXd& xty,
                  const std::vector<int>& cols, Eigen::VectorXd& w) {
  const int m = static_cast<int>(cols.size());
  Eigen::MatrixXd sub(m, m);
  Eigen::VectorXd rhs(m);
  for (int a = 0; a < m; ++a) {
    rhs(a) = xty(cols[a]);
    for (int b = 0; b < m; ++b) sub(a, b) = gram(cols[a], cols[b]);
  }
  w = Eigen::LDLT<Eigen::MatrixXd>(sub).solve(rhs);
  return w.allFinite();
}

OlsFit FitOls(const NormalEquations& eq, double threshold) {
  OlsFit fit;
  const int k = static_cast<int>(eq.gram.rows()) - 1;
  Eigen::MatrixXd g = eq.gram.selfadjointView<Eigen::Lower>();
  if (!g.allFinite() || !eq.xty.allFinite() || !std::isfinite(eq.yty) || eq.rows < 2) return fit;
  const double sst = eq.yty - eq.xty(0) * eq.xty(0) / static_cast<double>(eq.rows);
  if (!(sst > 0)) return fit;

  // Cholesky in term order, skipping dependent columns: r(j, l) and the projections q_j.
  Eigen::MatrixXd r = Eigen::MatrixXd::Zero(k + 1, k + 1);
  Eigen::VectorXd q = Eigen::VectorXd::Zero(k + 1);
  std::vector<bool> independent(k + 1, false);
  std::vector<double> err(k + 1, 0.0);
  for (int j = 0; j <= k; ++j) {
    double d = g(j, j);
    for (int i = 0; i < j; ++i)
      if (independent[i]) d -= r(i, j) * r(i, j);
    if (!(d > 1e-10 * std::max(g(j, j), 1e-300))) continue;
    independent[j] = true;
    r(j, j) = std::sqrt(d);
    for (int l = j + 1; l <= k; ++l) {
      double s = g(j, l);
      for (int i = 0; i < j; ++i)
        if (independent[i]) s -= r(i, j) * r(i, l);
      r(j, l) = s / r(j, j);
    }
    double s = eq.xty(j);
    for (int i = 0; i < j; ++i)
      if (independent[i]) s -= r(i, j) * q(i);
    q(j) = s / r(j, j);
    if (j > 0) err[j] = q(j) * q(j) / sst;
  }

  int best = -1;
  for (int j = 1; j <= k; ++j)
    if (independent[j] && (best < 0 || err[j] > err[best])) best = j;
  if (best < 0) return fit;
  std::vector<int> cols = {0};
  for (int j = 1; j <= k; ++j)
    if (independent[j] && (err[j] >= threshold || j == best)) cols.push_back(j);

  const int m = static_cast<int>(cols.size());
  Eigen::VectorXd w;
  if (!SolveColumns(g, eq.xty, cols, w)) return fit;
  Eigen::VectorXd rhs(m);
  for (int a = 0; a < m; ++a) rhs(a) = eq.xty(cols[a]);
  const double ssr = std::max(0.0, eq.yty - w.dot(rhs));
  fit.bias = w(0);
  for (int a = 1; a < m; ++a) {
    fit.kept.push_back(cols[a] - 1);
    fit.weights.push_back(w(a));
    fit.err.push_back(err[cols[a]]);
  }
  fit.r2 = 1.0 - ssr / sst;
  fit.r2_heldout = fit.r2;
  fit.mse = ssr / static_cast<double>(eq.rows);
  fit.valid = std::isfinite(fit.r2);
  return fit;
}

Tree SumOfTerms(const Tree& tree, const std::vector<int>& term_roots) {
  Tree out;
  for (size_t t = 0; t < term_roots.size(); ++t) {
    const int root = term_roots[t];
    out.insert(out.end(), tree.begin() + root + 1 - tree[root].length, tree.begin() + root + 1);
    if (t > 0) out.push_back({Op::kAdd, 0, 1, 0.0});
  }
  UpdateLengths(out);
  return out;
}

}  // namespace usvid::gp
