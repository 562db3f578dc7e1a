// GP-OLS (Madar, Abonyi & Szeifert 2002): the tree is split at the root's chain of + and -
// into terms; with a bias, their weights are fitted by least squares; each term's error
// reduction ratio
//   ERR_i = g_i^2 (w_i' w_i) / (y' y)
// is computed on the orthogonalised terms (classical Gram-Schmidt in term order, here from the
// Cholesky factor of the Gram matrix, with y centred by the bias); terms under the threshold
// are cut, always keeping the best, and the rest refitted. Linearly dependent terms have
// ERR 0. The Gram matrix is accumulated batch by batch, so rows never need to be stored.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "methods/gp/tree.h"

namespace usvid::gp {

// Roots of the additive terms of `tree`, left to right.
std::vector<int> SplitTerms(const Tree& tree);

// The normal equations of [1, t_1 .. t_k] against y, accumulated over rows.
struct NormalEquations {
  Eigen::MatrixXd gram;  // (k + 1) x (k + 1), column 0 the bias
  Eigen::VectorXd xty;
  double yty = 0.0;
  long rows = 0;

  explicit NormalEquations(int terms)
      : gram(Eigen::MatrixXd::Zero(terms + 1, terms + 1)), xty(Eigen::VectorXd::Zero(terms + 1)) {}
  // Adds `count` rows: term values column-major in x (count x k), targets in y.
  void Add(const Eigen::Ref<const Eigen::MatrixXd>& x, const Eigen::Ref<const Eigen::VectorXd>& y);
  // Adds the rows of another accumulation of the same terms.
  NormalEquations& operator+=(const NormalEquations& other);
};

// The weights of the columns `cols` of the full (symmetric) Gram matrix `gram` against `xty`
// (LDLT); false when they are not finite.
bool SolveColumns(const Eigen::MatrixXd& gram, const Eigen::VectorXd& xty,
                  const std::vector<int>& cols, Eigen::VectorXd& w);

struct OlsFit {
  std::vector<int> kept;        // indices into the term list, in order
  std::vector<double> weights;  // one per kept term
  std::vector<double> err;      // ERR of each kept term
  double bias = 0.0;
  double r2 = 0.0;
  double r2_heldout = 0.0;  // on held-out blocks (term_selection.h); r2 for a threshold fit
  double mse = 0.0;
  bool valid = false;  // false: degenerate data (no variance, non-finite values)
};

OlsFit FitOls(const NormalEquations& eq, double threshold);

// The tree rebuilt as the sum of the given terms (their subtrees joined by +).
Tree SumOfTerms(const Tree& tree, const std::vector<int>& term_roots);

}  // namespace usvid::gp
