#include "preprocessing/savitzky_golay.h"

#include <Eigen/QR>
#include <cmath>
#include <string>

#include "core/error.h"

namespace usvid {

Eigen::VectorXd SavitzkyGolay::Weights(int position, int derivative, double dt) const {
  // Least-squares polynomial in s = (k - position) dt: row d of pinv(X), times d!.
  Eigen::MatrixXd x(window, order + 1);
  for (int k = 0; k < window; ++k)
    for (int p = 0; p <= order; ++p) x(k, p) = std::pow((k - position) * dt, p);
  const Eigen::MatrixXd pinv =
      x.colPivHouseholderQr().solve(Eigen::MatrixXd::Identity(window, window));
  double factorial = 1.0;
  for (int d = 2; d <= derivative; ++d) factorial *= d;
  return pinv.row(derivative).transpose() * factorial;
}

Eigen::VectorXd SavitzkyGolay::Apply(const Eigen::VectorXd& y, double dt, int derivative) const {
  const std::string what = "Savitzky-Golay " + std::to_string(window) + ":" + std::to_string(order);
  if (window % 2 == 0 || window < order + 2)
    throw InputError(what + ": the window must be odd and at least order + 2");
  if (!(dt > 0)) throw InputError(what + ": the sample interval must be positive");
  if (derivative < 0 || derivative > order)
    throw InputError(what + ": derivative order must be within the polynomial order");
  const Eigen::Index n = y.size();
  if (n < window)
    throw InputError(what + ": the signal has " + std::to_string(n) +
                     " samples, fewer than the window");
  const int half = window / 2;
  Eigen::VectorXd out(n);
  const Eigen::VectorXd centre = Weights(half, derivative, dt);
  for (Eigen::Index i = half; i < n - half; ++i) out(i) = centre.dot(y.segment(i - half, window));
  for (int i = 0; i < half; ++i) {
    out(i) = Weights(i, derivative, dt).dot(y.head(window));
    out(n - 1 - i) = Weights(window - 1 - i, derivative, dt).dot(y.tail(window));
  }
  return out;
}

}  // namespace usvid
