// First-order wave motion (sensors/wave_motion.h): the displacement has the sea's statistics
// (RMS Hs / 4 along the waves' direction, none across it), the logged velocities are the rates
// of the logged positions at the encounter frequency, the yaw vanishes in head seas and not in
// quartering seas, short waves hardly move a long hull, and bad specs are refused.
#include "sensors/wave_motion.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.h"

namespace usvid {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// A vessel on a straight course `heading_deg` at `speed` m/s, at `hz` for `seconds`.
Dataset Straight(double heading_deg, double speed, double seconds = 3600.0, double hz = 20.0) {
  const auto n = static_cast<Eigen::Index>(seconds * hz) + 1;
  Dataset d(Eigen::VectorXd::LinSpaced(n, 0.0, seconds));
  const double psi = heading_deg * kDeg;
  d.Set("north", d.t() * speed * std::cos(psi));
  d.Set("east", d.t() * speed * std::sin(psi));
  d.Set("psi", Eigen::VectorXd::Constant(n, psi));
  d.Set("u", Eigen::VectorXd::Constant(n, speed));
  d.Set("v", Eigen::VectorXd::Zero(n));
  d.Set("r", Eigen::VectorXd::Zero(n));
  return d;
}

double Rms(const Eigen::VectorXd& x) { return std::sqrt(x.array().square().mean()); }

// At rest in beam seas from the west (they go east), with no hull to filter them, the east
// displacement's RMS is the elevation's, Hs / 4 (the components span 0.6-3 wp, most of the
// spectrum's area), and north does not move.
TEST(WaveMotionTest, DisplacementHasTheSeasStatistics) {
  const Dataset calm = Straight(0.0, 0.0);
  Dataset sea = calm;
  AddWaveMotion(sea, ParseWaveSea("2:6:270", 1, "test"), 0.0, 1);
  EXPECT_NEAR(Rms(sea["east"] - calm["east"]), 2.0 / 4, 0.05 * 2.0 / 4);
  EXPECT_LT(Rms(sea["north"] - calm["north"]), 1e-12);
  // Beam seas do not yaw the hull.
  EXPECT_LT(Rms(sea["psi"] - calm["psi"]), 1e-12);
}

// Under way at 6 m/s into quartering seas, the logged body velocities turned to the earth are
// the rates of the logged positions, and r the rate of psi, though the encounter frequency is
// not the waves' own (central differences over 0.02 s at 100 Hz, within 2 % of the motion).
TEST(WaveMotionTest, VelocitiesAreTheRatesOfThePositions) {
  const Dataset calm = Straight(10.0, 6.0, 600.0, 100.0);
  Dataset sea = calm;
  AddWaveMotion(sea, ParseWaveSea("1:5:55", 3, "test"), 0.0, 3);
  const Eigen::VectorXd& t = sea.t();
  double worst_north = 0, worst_psi = 0;
  for (Eigen::Index k = 1; k + 1 < sea.rows(); ++k) {
    const double dt = t(k + 1) - t(k - 1);
    const double psi = sea["psi"](k), u = sea["u"](k), v = sea["v"](k);
    const double north_rate = (sea["north"](k + 1) - sea["north"](k - 1)) / dt;
    worst_north =
        std::max(worst_north, std::abs(north_rate - (u * std::cos(psi) - v * std::sin(psi))));
    const double psi_rate = (sea["psi"](k + 1) - sea["psi"](k - 1)) / dt;
    worst_psi = std::max(worst_psi, std::abs(psi_rate - sea["r"](k)));
  }
  EXPECT_LT(worst_north, 0.02 * Rms(sea["u"] - calm["u"]) * 3);
  EXPECT_LT(worst_psi, 0.02 * Rms(sea["r"]) * 3);
  EXPECT_GT(Rms(sea["psi"] - calm["psi"]), 0.2 * kDeg);  // quartering seas yaw the hull
}

// Head seas do not yaw the hull; a 100 m hull hardly moves in a 0.5 m, 3 s sea (14 m waves)
// that moves a 5 m boat.
TEST(WaveMotionTest, HeadSeasAndLongHulls) {
  const Dataset calm = Straight(0.0, 3.0, 1200.0);
  Dataset head = calm;
  AddWaveMotion(head, ParseWaveSea("1:5:0", 2, "test"), 10.0, 2);
  EXPECT_LT(Rms(head["psi"] - calm["psi"]), 1e-9);
  EXPECT_GT(Rms(head["north"] - calm["north"]), 0.1);
  Dataset boat = calm, ship = calm;
  AddWaveMotion(boat, ParseWaveSea("0.5:3:30", 2, "test"), 5.0, 2);
  AddWaveMotion(ship, ParseWaveSea("0.5:3:30", 2, "test"), 100.0, 2);
  EXPECT_LT(Rms(ship["north"] - calm["north"]), 0.1 * Rms(boat["north"] - calm["north"]));
}

// A sparse channel stays sampled on its own rows.
TEST(WaveMotionTest, KeepsEachChannelsSampling) {
  Dataset d = Straight(0.0, 2.0, 60.0);
  Eigen::Array<bool, Eigen::Dynamic, 1> every_tenth(d.rows());
  for (Eigen::Index k = 0; k < d.rows(); ++k) every_tenth(k) = k % 10 == 0;
  d.Set("north", d["north"], every_tenth);
  AddWaveMotion(d, ParseWaveSea("1", 4, "test"), 10.0, 4);
  EXPECT_EQ(d.Get("north").SampleCount(), (d.rows() + 9) / 10);
  EXPECT_TRUE(d.Get("east").FullySampled());
}

TEST(WaveMotionTest, BadSpecsAreRefused) {
  EXPECT_THROW(ParseWaveSea("0", 1, "--waves"), InputError);
  EXPECT_THROW(ParseWaveSea("2:0.5", 1, "--waves"), InputError);
  EXPECT_THROW(ParseWaveSea("2:x", 1, "--waves"), InputError);
  EXPECT_THROW(ParseWaveSea("", 1, "--waves"), InputError);
  EXPECT_NEAR(ParseWaveSea("4", 1, "--waves").tp, 10.0, 1e-12);  // 5 sqrt(Hs)
  Dataset no_heading(Eigen::VectorXd::LinSpaced(3, 0, 1));
  no_heading.Set("x", Eigen::VectorXd::Zero(3));
  EXPECT_THROW(AddWaveMotion(no_heading, ParseWaveSea("1", 1, "--waves"), 0.0, 1), InputError);
}

}  // namespace
}  // namespace usvid
