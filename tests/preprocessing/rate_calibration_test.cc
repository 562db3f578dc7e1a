// A gyro's offset and scale error against the heading (preprocessing/rate_calibration.h): a
// heading from a zig-zag-like yaw motion, and a rate of turn that reads it with a known offset
// and scale error plus noise. The calibration recovers both and the true rate; a straight run
// cannot tell the scale and leaves it 0; a rate in the wrong units is refused.
#include "preprocessing/rate_calibration.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/dataset.h"
#include "core/error.h"

namespace usvid {
namespace {

// psi(t) = a sin(0.04 t) + drift t at 10 Hz for 600 s, heading noise 0.001 rad; the gyro reads
// r = (1 + k) psi' + b with noise 1e-4 rad/s.
Dataset Record(double amplitude, double drift, double k, double b) {
  constexpr double kDt = 0.1;
  constexpr int kN = 6001;
  std::mt19937_64 rng(7);
  std::normal_distribution<double> noise(0.0, 1.0);
  Eigen::VectorXd t(kN), psi(kN), r(kN);
  for (int i = 0; i < kN; ++i) {
    t(i) = i * kDt;
    psi(i) = amplitude * std::sin(0.04 * t(i)) + drift * t(i) + 0.001 * noise(rng);
    r(i) = (1.0 + k) * (0.04 * amplitude * std::cos(0.04 * t(i)) + drift) + b + 1e-4 * noise(rng);
  }
  Dataset d(t);
  d.Set("psi", psi);
  d.Set("r", r);
  return d;
}

TEST(RateCalibrationTest, RecoversTheGyrosOffsetAndScaleErrorAndTheTrueRate) {
  const Dataset d = Record(0.35, 0.001, -0.015, 1.0e-4);
  const RateCalibration c = EstimateRateCalibration(d, "psi");
  EXPECT_NEAR(c.offset, 1.0e-4, 5e-6);
  EXPECT_NEAR(c.scale_error, -0.015, 1e-3);
  EXPECT_LT(c.residual_rad, 0.003);
  const Eigen::VectorXd r = CalibratedRate(d, c);
  double worst = 0.0;
  for (Eigen::Index i = 0; i < d.rows(); ++i)
    worst = std::max(worst, std::abs(r(i) - (0.014 * std::cos(0.04 * d.t()(i)) + 0.001)));
  EXPECT_LT(worst, 6e-4);  // the gyro's own noise, not its offset or scale
}

TEST(RateCalibrationTest, AStraightRunLeavesTheScaleAlone) {
  // The heading spans 0.006 rad: only the offset can be told.
  const Dataset d = Record(0.0, 1.0e-5, 0.05, -2.0e-4);
  const RateCalibration c = EstimateRateCalibration(d, "psi");
  EXPECT_EQ(c.scale_error, 0.0);
  EXPECT_NEAR(c.offset, -2.0e-4, 1e-5);
}

TEST(RateCalibrationTest, RefusesARateInOtherUnitsOrAMissingHeading) {
  Dataset d = Record(0.35, 0.0, 0.0, 0.0);
  d.Set("r", Eigen::VectorXd(d["r"] * 180.0 / 3.14159265358979));  // deg/s
  EXPECT_THROW(EstimateRateCalibration(d, "psi"), InputError);
  EXPECT_THROW(EstimateRateCalibration(d, "chi"), InputError);
}

}  // namespace
}  // namespace usvid
