// Multi-rate logs onto one time base (issue 4 acceptance): a log with 50 Hz, 5 Hz and 10 Hz
// channels resampled to 20 Hz keeps every channel within its noise level of the truth; long
// gaps are not bridged, and the report says so.
#include "preprocessing/resample.h"

#include <gtest/gtest.h>

#include <cmath>

#include "maneuvers/maneuver_factory.h"
#include "sensors/noise.h"
#include "sensors/sample_rates.h"
#include "simulation/vessel_simulator.h"

namespace usvid {
namespace {

class ResampleTest : public ::testing::Test {};

TEST_F(ResampleTest, MultiRateLogKeepsEachChannelWithinItsNoise) {
  const VesselSimulator& sim = FindVessel("odin-hs");
  RunOptions opt;
  opt.rate_hz = 100.0;  // the truth, on a grid the 20 Hz points fall on
  auto m = MakeManeuver("random-steps", sim.Info().actuation, 300.0, 3);
  const Dataset clean = sim.RunManeuver(*m, sim.Info().default_params, {}, opt).data;
  Dataset noisy = clean;
  const std::vector<std::string> channels = {"north", "east", "psi",          "u", "v",
                                             "r",     "rpm",  "nozzle_angle", "U"};
  const std::vector<double> sd = AddGaussianNoise(noisy, channels, 0.01, 5);
  ApplySampleRates(noisy, ParseSampleRates({"imu=50", "gps=5", "jet=10"}, noisy));
  for (const Interpolation kind : {Interpolation::kLinear, Interpolation::kCubicSpline}) {
    ResampleOptions ro;
    ro.rate_hz = 20.0;
    ro.interpolation = kind;
    ResampleReport report;
    const Dataset out = Resample(noisy, ro, &report);
    EXPECT_EQ(out.rows(), 6001);
    for (size_t c = 0; c < channels.size(); ++c) {
      double sum = 0.0;
      long count = 0;
      for (Eigen::Index k = 0; k < out.rows(); ++k) {
        if (!out.Get(channels[c]).IsSampled(k)) continue;
        const double truth = clean[channels[c]](k * 5);
        sum += std::pow(out[channels[c]](k) - truth, 2);
        ++count;
      }
      EXPECT_GT(count, 5990) << channels[c];
      EXPECT_LE(std::sqrt(sum / count), sd[c])
          << channels[c] << " interpolation " << static_cast<int>(kind);
    }
  }
}

// A channel that stops for 10 s is left empty there instead of being drawn straight across.
TEST_F(ResampleTest, LongGapsAreNotBridged) {
  const int n = 1001;
  Dataset d(Eigen::VectorXd::LinSpaced(n, 0.0, 100.0));
  Eigen::Array<bool, Eigen::Dynamic, 1> s = Eigen::Array<bool, Eigen::Dynamic, 1>::Ones(n);
  s.segment(400, 100) = false;  // 40 s to 50 s missing
  d.Set("x", d.t(), s);
  ResampleReport report;
  const Dataset out = Resample(
      d, {.rate_hz = 2.0, .interpolation = Interpolation::kLinear, .channels = {}}, &report);
  EXPECT_EQ(report.channels.at(0).gaps, 1);
  for (Eigen::Index k = 0; k < out.rows(); ++k) {
    const double t = out.t()(k);
    EXPECT_EQ(out.Get("x").IsSampled(k), !(t > 39.95 && t < 50.0)) << t;
    if (out.Get("x").IsSampled(k)) {
      EXPECT_NEAR(out["x"](k), t, 1e-9);
    }
  }
  EXPECT_NE(report.Summary().at(0).find("1 gap(s) not bridged"), std::string::npos);
}

}  // namespace
}  // namespace usvid
