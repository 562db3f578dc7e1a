#include "methods/gp/term_selection.h"

#include <algorithm>
#include <cmath>

namespace usvid::gp {
namespace {

// y_b'y_b - 2 w' X_b'y_b + w' X_b'X_b w over the columns `cols`.
double BlockSse(const NormalEquations& b, const Eigen::MatrixXd& gb, const std::vector<int>& cols,
                const Eigen::VectorXd& w) {
  double sse = b.yty;
  for (size_t a = 0; a < cols.size(); ++a) {
    sse -= 2.0 * w(static_cast<Eigen::Index>(a)) * b.xty(cols[a]);
    for (size_t c = 0; c < cols.size(); ++c)
      sse +=
          w(static_cast<Eigen::Index>(a)) * gb(cols[a], cols[c]) * w(static_cast<Eigen::Index>(c));
  }
  return std::max(0.0, sse);
}

// Forward orthogonal order of the independent terms (column indices >= 1) with their ERR.
void ForwardOrder(const Eigen::MatrixXd& g, const Eigen::VectorXd& xty, double sst,
                  std::vector<int>& order, std::vector<double>& err) {
  const int k = static_cast<int>(g.rows()) - 1;
  // Row s of r and entry s of q belong to the s-th chosen column (the bias first).
  Eigen::MatrixXd r = Eigen::MatrixXd::Zero(k + 1, k + 1);
  Eigen::VectorXd q = Eigen::VectorXd::Zero(k + 1);
  std::vector<bool> chosen(k + 1, false);
  auto add = [&](int step, int j, double d) {
    chosen[j] = true;
    const double rjj = std::sqrt(d);
    for (int l = 0; l <= k; ++l) {
      if (chosen[l] && l != j) continue;
      double s = g(j, l);
      for (int i = 0; i < step; ++i) s -= r(i, j) * r(i, l);
      r(step, l) = s / rjj;
    }
    double s = xty(j);
    for (int i = 0; i < step; ++i) s -= r(i, j) * q(i);
    q(step) = s / rjj;
  };
  if (!(g(0, 0) > 0)) return;
  add(0, 0, g(0, 0));
  for (int step = 1; step <= k; ++step) {
    int best = -1;
    double best_err = -1.0, best_d = 0.0;
    for (int j = 1; j <= k; ++j) {
      if (chosen[j]) continue;
      double d = g(j, j), s = xty(j);
      for (int i = 0; i < step; ++i) {
        d -= r(i, j) * r(i, j);
        s -= r(i, j) * q(i);
      }
      if (!(d > 1e-10 * std::max(g(j, j), 1e-300))) continue;  // dependent on those chosen
      const double e = s * s / d / sst;
      if (e > best_err) {
        best = j;
        best_err = e;
        best_d = d;
      }
    }
    if (best < 0) break;
    add(step, best, best_d);
    order.push_back(best);
    err.push_back(best_err);
  }
}

// The held-out SSE of each prefix of the forward order (index m: the first m terms and the
// bias), per block: each block scored by the fit to the other blocks' rows.
std::vector<std::vector<double>> HeldOutSse(const std::vector<NormalEquations>& blocks,
                                            const Eigen::MatrixXd& g, const Eigen::VectorXd& xty,
                                            const std::vector<int>& order) {
  // Each block's own Gram matrix, and the others' (the rows that fit what the block scores).
  std::vector<Eigen::MatrixXd> block_gram, rest_gram;
  std::vector<Eigen::VectorXd> rest_xty;
  for (const NormalEquations& b : blocks) {
    block_gram.push_back(b.gram.selfadjointView<Eigen::Lower>());
    rest_gram.push_back(g - block_gram.back());
    rest_xty.push_back(xty - b.xty);
  }
  std::vector<std::vector<double>> sse(order.size() + 1);
  std::vector<int> cols = {0};
  for (size_t m = 1; m <= order.size(); ++m) {
    cols.push_back(order[m - 1]);
    for (size_t b = 0; b < blocks.size(); ++b) {
      Eigen::VectorXd w;
      if (blocks[b].rows == 0) {
        sse[m].push_back(0.0);
      } else if (SolveColumns(rest_gram[b], rest_xty[b], cols, w)) {
        sse[m].push_back(BlockSse(blocks[b], block_gram[b], cols, w));
      } else {
        sse[m].push_back(INFINITY);
      }
    }
  }
  return sse;
}

// The one-standard-error rule on paired block differences: the shortest prefix whose held-out
// SSE exceeds the best prefix's by no more than one standard error of that excess.
size_t OneStandardErrorPrefix(const std::vector<std::vector<double>>& sse, size_t best) {
  const size_t blocks = sse[best].size();
  const double k = static_cast<double>(blocks);
  for (size_t m = 1; m < best && k > 1; ++m) {
    double mean = 0.0, var = 0.0;
    for (size_t b = 0; b < blocks; ++b) mean += (sse[m][b] - sse[best][b]) / k;
    for (size_t b = 0; b < blocks; ++b) {
      const double d = sse[m][b] - sse[best][b] - mean;
      var += d * d / (k - 1);
    }
    if (std::isfinite(mean) && mean <= std::sqrt(var / k)) return m;
  }
  return best;
}

}  // namespace

OlsFit FitOlsHeldOut(const std::vector<NormalEquations>& blocks) {
  OlsFit fit;
  if (blocks.empty()) return fit;
  NormalEquations total = blocks[0];
  for (size_t b = 1; b < blocks.size(); ++b) total += blocks[b];
  const Eigen::MatrixXd g = total.gram.selfadjointView<Eigen::Lower>();
  if (!g.allFinite() || !total.xty.allFinite() || !std::isfinite(total.yty) || total.rows < 2)
    return fit;
  const double sst = total.yty - total.xty(0) * total.xty(0) / static_cast<double>(total.rows);
  if (!(sst > 0)) return fit;

  std::vector<int> order;
  std::vector<double> err;
  ForwardOrder(g, total.xty, sst, order, err);
  if (order.empty()) return fit;

  const std::vector<std::vector<double>> sse = HeldOutSse(blocks, g, total.xty, order);
  auto total_of = [&](size_t m) {
    double t = 0.0;
    for (double e : sse[m]) t += e;
    return t;
  };
  size_t best = 0;
  for (size_t m = 1; m <= order.size(); ++m)
    if (best == 0 || total_of(m) < total_of(best)) best = m;
  if (!std::isfinite(total_of(best))) best = 1;
  const size_t best_terms = OneStandardErrorPrefix(sse, best);
  const double best_sse = total_of(best_terms);

  // The kept terms in their order in the tree, refitted on all rows.
  std::vector<std::pair<int, double>> kept;
  for (size_t m = 0; m < best_terms; ++m) kept.emplace_back(order[m], err[m]);
  std::sort(kept.begin(), kept.end());
  std::vector<int> cols = {0};
  for (const auto& [j, _] : kept) cols.push_back(j);
  Eigen::VectorXd w;
  if (!SolveColumns(g, total.xty, cols, w)) return fit;
  double rhs_dot = 0.0;
  for (size_t a = 0; a < cols.size(); ++a)
    rhs_dot += w(static_cast<Eigen::Index>(a)) * total.xty(cols[a]);
  const double ssr = std::max(0.0, total.yty - rhs_dot);
  fit.bias = w(0);
  for (size_t a = 1; a < cols.size(); ++a) {
    fit.kept.push_back(kept[a - 1].first - 1);
    fit.weights.push_back(w(static_cast<Eigen::Index>(a)));
    fit.err.push_back(kept[a - 1].second);
  }
  fit.r2 = 1.0 - ssr / sst;
  fit.r2_heldout = std::isfinite(best_sse) ? 1.0 - best_sse / sst : fit.r2;
  fit.mse = ssr / static_cast<double>(total.rows);
  fit.valid = std::isfinite(fit.r2) && std::isfinite(fit.r2_heldout);
  return fit;
}

}  // namespace usvid::gp
