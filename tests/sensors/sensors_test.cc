// Sensors: seeded Gaussian noise of the stated level per channel, and multi-rate sampling that
// leaves the rows between a sensor's samples empty.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "sensors/noise.h"
#include "sensors/sample_rates.h"

namespace usvid {
namespace {

class SensorsTest : public ::testing::Test {
 protected:
  static Dataset Signals(int n = 20001) {
    Dataset d(Eigen::VectorXd::LinSpaced(n, 0.0, (n - 1) * 0.02));
    d.Set("u", (d.t().array() * 0.1).sin().matrix() * 3.0);
    d.Set("r", (d.t().array() * 0.3).cos().matrix() * 0.2);
    d.Set("north", d.t() * 5.0);
    return d;
  }
};

// The noise has zero mean and standard deviation level x the clean channel's, independently
// per channel; the same seed gives the same noise, another seed other noise.
TEST_F(SensorsTest, NoiseHasTheStatedLevelAndIsSeeded) {
  const Dataset clean = Signals();
  Dataset a = clean, b = clean, c = clean;
  const auto sds = AddGaussianNoise(a, {"u", "r"}, 0.01, 9);
  AddGaussianNoise(b, {"u", "r"}, 0.01, 9);
  AddGaussianNoise(c, {"u", "r"}, 0.01, 10);
  const Eigen::ArrayXd e = (a["u"] - clean["u"]).array();
  const double sd_u = 3.0 / std::sqrt(2.0) * 0.01;  // a sine of amplitude 3 over many periods
  EXPECT_NEAR(sds[0], sd_u, 0.02 * sd_u);
  EXPECT_NEAR(std::sqrt(e.square().mean()), sds[0], 0.03 * sds[0]);
  EXPECT_NEAR(e.mean(), 0.0, 4 * sds[0] / std::sqrt(e.size()));
  EXPECT_EQ(a["u"], b["u"]);
  EXPECT_NE(a["u"], c["u"]);
  EXPECT_EQ(a["north"], clean["north"]);
  // Noise on u does not depend on whether r is noised too.
  Dataset only_u = clean;
  AddGaussianNoise(only_u, {"u"}, 0.01, 9);
  EXPECT_EQ(only_u["u"], a["u"]);
}

// At 50 Hz data, a 5 Hz GPS keeps every tenth row and a 10 Hz jet feedback every fifth; the
// kept values are untouched.
TEST_F(SensorsTest, SampleRatesLeaveRowsBetweenSamplesEmpty) {
  Dataset d = Signals(501);
  const Dataset clean = d;
  ApplySampleRates(d, ParseSampleRates({"gps=5", "r=10"}, d));
  const Channel& gps = d.Get("north");
  EXPECT_EQ(gps.SampleCount(), 51);
  for (Eigen::Index k = 0; k < d.rows(); ++k) {
    EXPECT_EQ(gps.IsSampled(k), k % 10 == 0) << k;
    EXPECT_EQ(d.Get("r").IsSampled(k), k % 5 == 0) << k;
    if (gps.IsSampled(k)) {
      EXPECT_EQ(gps.Value(k), clean["north"](k));
    }
  }
  EXPECT_TRUE(d.Get("u").FullySampled());
  EXPECT_THROW(ParseSampleRates({"gps=-5"}, d), InputError);
  EXPECT_THROW(ParseSampleRates({"lidar=5"}, d), InputError);
}

}  // namespace
}  // namespace usvid
