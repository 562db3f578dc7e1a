// Sensor dropouts (sensors/dropouts.h): over two hours a GPS loses the stated share of its
// samples in gaps of about 2 s, every GPS channel the same rows and no other sensor any; the
// gaps are seeded, and bad items are refused.
#include "sensors/dropouts.h"

#include <gtest/gtest.h>

#include "core/error.h"

namespace usvid {
namespace {

Dataset Log(double seconds = 7200.0) {
  const auto n = static_cast<Eigen::Index>(seconds * 10) + 1;
  Dataset d(Eigen::VectorXd::LinSpaced(n, 0.0, seconds));
  for (const char* name : {"north", "east", "U", "chi", "psi", "u", "v", "r"})
    d.Set(name, Eigen::VectorXd::Constant(n, 1.0));
  return d;
}

TEST(DropoutsTest, LosesTheStatedShareInGaps) {
  Dataset d = Log();
  ApplyDropouts(d, ParseDropouts({"gps=0.1"}), 5);
  const Channel& north = d.Get("north");
  const double lost =
      1.0 - static_cast<double>(north.SampleCount()) / static_cast<double>(d.rows());
  EXPECT_NEAR(lost, 0.1, 0.02);
  // Gaps: runs of lost rows, 0.1 s apart.
  int gaps = 0;
  for (Eigen::Index k = 1; k < d.rows(); ++k)
    gaps += north.IsSampled(k - 1) && !north.IsSampled(k) ? 1 : 0;
  const double mean_gap = lost * 7200.0 / gaps;
  EXPECT_NEAR(mean_gap, kMeanGapS, 0.25 * kMeanGapS);
  for (const char* name : {"east", "U", "chi"})
    for (Eigen::Index k = 0; k < d.rows(); ++k)
      ASSERT_EQ(d.Get(name).IsSampled(k), north.IsSampled(k)) << name << " row " << k;
  for (const char* name : {"psi", "u", "v", "r"}) EXPECT_TRUE(d.Get(name).FullySampled());
}

TEST(DropoutsTest, SeededPerSensor) {
  Dataset a = Log(600), b = Log(600), c = Log(600);
  ApplyDropouts(a, ParseDropouts({"gps=0.2", "imu=0.2"}), 1);
  ApplyDropouts(b, ParseDropouts({"gps=0.2"}), 1);
  ApplyDropouts(c, ParseDropouts({"gps=0.2"}), 2);
  auto same = [](const Channel& x, const Channel& y) { return (x.sampled() == y.sampled()).all(); };
  EXPECT_TRUE(same(a.Get("north"), b.Get("north")));  // imu's gaps move no GPS gap
  EXPECT_FALSE(same(a.Get("north"), c.Get("north")));
  EXPECT_FALSE(same(a.Get("north"), a.Get("psi")));
}

TEST(DropoutsTest, BadItemsAreRefused) {
  EXPECT_THROW(ParseDropouts({"gps"}), InputError);
  EXPECT_THROW(ParseDropouts({"gps=1"}), InputError);
  EXPECT_THROW(ParseDropouts({"gps=-0.1"}), InputError);
  EXPECT_THROW(ParseDropouts({"=0.1"}), InputError);
  Dataset d = Log(10);
  EXPECT_THROW(ApplyDropouts(d, ParseDropouts({"sonar=0.1"}), 1), InputError);
}

}  // namespace
}  // namespace usvid
