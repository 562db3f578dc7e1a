#include "preprocessing/rate_calibration.h"

#include <Eigen/QR>
#include <cmath>
#include <sstream>

#include "core/angles.h"
#include "core/error.h"

namespace usvid {
namespace {

const Eigen::VectorXd& SampledChannel(const Dataset& data, const std::string& name,
                                      const std::string& what) {
  const Channel* c = data.Find(name);
  if (c == nullptr) throw InputError(data.SourcePrefix() + "no " + what + " column '" + name + "'");
  if (!c->FullySampled())
    throw InputError(data.SourcePrefix() + what + " '" + name +
                     "' has empty cells: resample it first");
  return c->values();
}

}  // namespace

RateCalibration EstimateRateCalibration(const Dataset& data, const std::string& heading) {
  const Eigen::VectorXd psi = UnwrappedAngle(SampledChannel(data, heading, "heading"));
  const Eigen::VectorXd& r = SampledChannel(data, "r", "rate of turn");
  const Eigen::Index n = data.rows();
  if (n < 10) throw InputError(data.SourcePrefix() + "the rate's calibration needs 10 rows");
  const Eigen::VectorXd& t = data.t();
  // e = int r dt - (psi - psi_0), the integral by the trapezoidal rule.
  Eigen::VectorXd e(n);
  double integral = 0.0;
  e(0) = 0.0;
  for (Eigen::Index k = 1; k < n; ++k) {
    integral += 0.5 * (r(k - 1) + r(k)) * (t(k) - t(k - 1));
    e(k) = integral - (psi(k) - psi(0));
  }
  const Eigen::VectorXd turned = psi.array() - psi(0);
  const bool scale = turned.maxCoeff() - turned.minCoeff() >= 0.05;
  Eigen::MatrixXd x(n, scale ? 3 : 2);
  x.col(0) = t.array() - t(0);
  x.col(1).setOnes();
  if (scale) x.col(2) = turned;
  const Eigen::VectorXd beta = x.colPivHouseholderQr().solve(e);
  RateCalibration c;
  c.offset = beta(0);
  c.scale_error = scale ? beta(2) : 0.0;
  c.residual_rad = std::sqrt((e - x * beta).squaredNorm() / static_cast<double>(n));
  if (!(std::abs(c.scale_error) <= 0.2))
    throw InputError(data.SourcePrefix() + "the rate of turn r reads " +
                     std::to_string(1.0 + c.scale_error) + " times the change of heading '" +
                     heading +
                     "': not one motion in the same units (r in rad/s, the heading in rad)");
  return c;
}

Eigen::VectorXd CalibratedRate(const Dataset& data, const RateCalibration& calibration) {
  return (data["r"].array() - calibration.offset) / (1.0 + calibration.scale_error);
}

std::string DescribeRateCalibration(const RateCalibration& c, const std::string& heading) {
  std::ostringstream s;
  s.precision(3);
  s << "r calibrated against " << heading << ": offset " << c.offset << " rad/s, scale error "
    << 100.0 * c.scale_error << " %, the heading's residual " << c.residual_rad << " rad RMS";
  return s.str();
}

}  // namespace usvid
