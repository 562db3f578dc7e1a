// Turning-circle figures of merit (ITTC 7.5-04-02-01, IMO MSC.137(76)) read from a record: on a
// straight approach followed by an exact circle the analysis finds advance = transfer = R,
// tactical diameter 2R and the steady rate U / R, turning either way and with either rudder
// sign or a yaw moment; on odin3dof's simulated turning circle it agrees with the maneuver's
// own report; unreached figures are NaN, and records without a channel, or whose rudder never
// moves, are refused.
#include "metrics/turning_response.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "core/dataset.h"
#include "core/error.h"
#include "maneuvers/maneuver_factory.h"
#include "simulation/vessel_simulator.h"

namespace usvid {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kU = 5.0, kR = 50.0, kDt = 0.05, kExecute = 10.0;
constexpr double kPsi0 = 0.4, kNorth0 = 100.0, kEast0 = -50.0;
// Linear interpolation across a chord of the circle is off by at most R (r dt)^2 / 8.
constexpr double kChordTol = 1e-3;

// At U along psi0 until kExecute, where the ship is at (kNorth0, kEast0), then on a circle of
// radius kR to `side` (+1 starboard) at the same speed, for `turn_s` seconds: psi = psi0 + side
// U / R (t - execute), centre R to the side of the origin. delta is 0, then side 35 deg.
Dataset StraightThenCircle(int side, double turn_s = 120.0) {
  const int n = static_cast<int>(std::lround((kExecute + turn_s) / kDt)) + 1;
  Eigen::VectorXd t(n), psi(n), north(n), east(n), delta(n);
  const double cn = kNorth0 - side * kR * std::sin(kPsi0);
  const double ce = kEast0 + side * kR * std::cos(kPsi0);
  for (int k = 0; k < n; ++k) {
    t(k) = k * kDt;
    const double since = t(k) - kExecute;
    if (k < std::lround(kExecute / kDt)) {
      psi(k) = kPsi0;
      north(k) = kNorth0 + kU * since * std::cos(kPsi0);
      east(k) = kEast0 + kU * since * std::sin(kPsi0);
      delta(k) = 0.0;
    } else {
      psi(k) = kPsi0 + side * kU / kR * since;
      north(k) = cn + side * kR * std::sin(psi(k));
      east(k) = ce - side * kR * std::cos(psi(k));
      delta(k) = side * 35 * kDeg;
    }
  }
  Dataset d(t);
  d.Set("psi", psi);
  d.Set("north", north);
  d.Set("east", east);
  d.Set("delta", delta);
  return d;
}

void ExpectCircle(const TurningResponse& z, int side, const std::string& what) {
  EXPECT_NEAR(z.execute_s, kExecute, 1e-9) << what;
  EXPECT_EQ(z.direction, side) << what;
  EXPECT_TRUE(z.reached_90) << what;
  EXPECT_TRUE(z.reached_180) << what;
  EXPECT_NEAR(z.advance_m, kR, kChordTol) << what;
  EXPECT_NEAR(z.transfer_m, kR, kChordTol) << what;
  EXPECT_NEAR(z.tactical_diameter_m, 2 * kR, kChordTol) << what;
  EXPECT_NEAR(z.steady_rate_deg_s, kU / kR / kDeg, 1e-9) << what;
  EXPECT_NEAR(z.steady_radius_m, kR, 1e-6) << what;
}

// An exact circle: advance and transfer are the radius, the tactical diameter twice it, the
// steady rate U / R and the fitted radius R, to starboard and to port.
TEST(TurningResponseTest, AnalyticCircleGivesItsGeometry) {
  ExpectCircle(AnalyseTurning(StraightThenCircle(+1)), +1, "starboard");
  ExpectCircle(AnalyseTurning(StraightThenCircle(-1)), -1, "port");
}

// The ITTC rudder sign (positive to port) gives the same figures: the direction is read from
// the heading.
// An operator who swings the rudder past the test's angle before the order (to port, 40 deg, for
// 3 s, while the heading holds) makes that swing the command's largest: the 35 deg order is then
// not at full angle, and the execute falls back to the swing. Given the test's angle (turning:35)
// the execute is the order's, and the circle's figures are exact.
TEST(TurningResponseTest, TheTestsAngleFindsTheExecutePastAnOperatorsWiderSwing) {
  Dataset d = StraightThenCircle(+1);
  Eigen::VectorXd delta = d["delta"];
  for (Eigen::Index k = 0; k < d.rows(); ++k)
    if (d.t()(k) >= kExecute - 5.0 && d.t()(k) < kExecute - 2.0) delta(k) = -40 * kDeg;
  d.Set("delta", delta);
  ExpectCircle(AnalyseTurning(d, "psi", "delta", "north", "east", true, 35.0), +1, "given 35");
  EXPECT_NEAR(AnalyseTurning(d).execute_s, kExecute - 5.0, 1e-9);  // the swing, not the order
}

TEST(TurningResponseTest, RudderSignConventionDoesNotMatter) {
  for (int side : {+1, -1}) {
    Dataset d = StraightThenCircle(side);
    d.Set("delta", -d["delta"]);
    ExpectCircle(AnalyseTurning(d), side, "flipped rudder, side " + std::to_string(side));
  }
}

// A log's heading wraps at +-pi (Esso Osaka's psi_hat): the same circle, its heading wrapped,
// gives the same figures, the steady turn's among them, which need 540 deg of turn.
TEST(TurningResponseTest, AWrappedHeadingGivesTheSameFigures) {
  for (int side : {+1, -1}) {
    Dataset d = StraightThenCircle(side);
    Eigen::VectorXd psi = d["psi"];
    for (double& p : psi) p = std::remainder(p, 2.0 * std::numbers::pi);
    ASSERT_GT((psi - d["psi"]).cwiseAbs().maxCoeff(), 6.0);  // it does wrap
    d.Set("psi", psi);
    ExpectCircle(AnalyseTurning(d), side, "wrapped heading, side " + std::to_string(side));
  }
}

// A yaw moment executes when it moves by more than 1 % of its largest value: a 150 N m ripple
// on the approach (0.75 % of 20 kN m) is not the execute, the step to 20 kN m is.
TEST(TurningResponseTest, YawMomentExecutesAtOnePercentOfItsLargest) {
  Dataset d = StraightThenCircle(+1);
  Eigen::VectorXd tau_n = 20000.0 * d["delta"].cwiseSign();
  for (Eigen::Index k = 0; k < std::lround(kExecute / kDt); ++k) tau_n(k) = k % 2 ? 150.0 : 0.0;
  d.Set("tau_n", tau_n);
  d.Remove("delta");
  ExpectCircle(AnalyseTurning(d, "psi", "tau_n"), +1, "yaw moment");
}

// Positions logged at a fifth of the heading's rate (NaN between) are interpolated over their
// own samples.
TEST(TurningResponseTest, UnsampledPositionsAreInterpolatedOverTheirSamples) {
  Dataset d = StraightThenCircle(-1);
  Eigen::Array<bool, Eigen::Dynamic, 1> gps(d.rows());
  for (Eigen::Index k = 0; k < d.rows(); ++k) gps(k) = k % 5 == 0;
  d.Set("north", d["north"], gps);
  d.Set("east", d["east"], gps);
  const TurningResponse z = AnalyseTurning(d);
  EXPECT_EQ(z.direction, -1);
  EXPECT_NEAR(z.advance_m, kR, 25 * kChordTol);
  EXPECT_NEAR(z.transfer_m, kR, 25 * kChordTol);
  EXPECT_NEAR(z.tactical_diameter_m, 2 * kR, 25 * kChordTol);
  EXPECT_NEAR(z.steady_radius_m, kR, 1e-6);
}

// Noise of 2 % of each channel's standard deviation (as `usvid simulate --noise 0.02` adds it):
// on the unwrapped heading of two and a half turns that is 5 deg, which moves the instants the
// turn passes 90 and 180 deg by about a second, and the positions read there with them. Read from
// the smoothed channels (metrics/criteria_smoothing.h), advance, transfer and tactical diameter
// stay within 1.5 % of those read from the clean record (read from the raw channels, they were
// 2-3 %, 6-9 % and 2.6 % off). The yaw rate builds up as a
// ship's does, with a 5 s lag: the smoothing rounds a heading whose rate steps, as
// StraightThenCircle's does, and then reads the advance up to 6 % long.
TEST(TurningResponseTest, NoiseOnTheHeadingAndPositionsMovesNoFigure) {
  constexpr double kLag = 5.0, kTurnS = 150.0;
  const int n = static_cast<int>(std::lround((kExecute + kTurnS) / kDt)) + 1;
  for (int side : {+1, -1}) {
    Eigen::VectorXd t(n), psi(n), north(n), east(n), delta(n);
    double p = kPsi0, r = 0.0, x = kNorth0, y = kEast0;
    for (int k = 0; k < n; ++k) {
      t(k) = k * kDt;
      delta(k) = t(k) >= kExecute - 1e-9 ? side * 35 * kDeg : 0.0;
      psi(k) = p, north(k) = x, east(k) = y;
      const double rate = delta(k) == 0.0 ? 0.0 : side * kU / kR;
      for (int s = 0; s < 100; ++s) {  // Euler on a grid 100 times finer than the record's
        const double h = kDt / 100;
        x += kU * std::cos(p) * h;
        y += kU * std::sin(p) * h;
        p += r * h;
        r += (rate - r) / kLag * h;
      }
    }
    Dataset d(t);
    d.Set("psi", psi);
    d.Set("north", north);
    d.Set("east", east);
    d.Set("delta", delta);
    const TurningResponse clean = AnalyseTurning(d);
    std::mt19937 rng(11);
    for (const char* c : {"psi", "north", "east"}) {
      Eigen::VectorXd x = d[c];
      const double sd = 0.02 * std::sqrt((x.array() - x.mean()).square().mean());
      if (std::string(c) == "psi") {
        ASSERT_GT(sd, 4 * kDeg);
      }
      std::normal_distribution<double> noise(0.0, sd);
      for (double& v : x) v += noise(rng);
      d.Set(c, x);
    }
    const TurningResponse z = AnalyseTurning(d);
    const std::string what = "side " + std::to_string(side);
    EXPECT_EQ(z.direction, side) << what;
    EXPECT_NEAR(z.advance_m, clean.advance_m, 0.015 * clean.advance_m) << what;
    EXPECT_NEAR(z.transfer_m, clean.transfer_m, 0.015 * clean.transfer_m) << what;
    EXPECT_NEAR(z.tactical_diameter_m, clean.tactical_diameter_m, 0.015 * clean.tactical_diameter_m)
        << what;
  }
}

// A record that ends before 180 deg, or before 360 deg more, leaves those figures NaN.
TEST(TurningResponseTest, UnreachedFiguresAreNaN) {
  const double rate = kU / kR;
  const TurningResponse short_turn = AnalyseTurning(StraightThenCircle(+1, 120 * kDeg / rate));
  EXPECT_TRUE(short_turn.reached_90);
  EXPECT_NEAR(short_turn.advance_m, kR, kChordTol);
  EXPECT_FALSE(short_turn.reached_180);
  EXPECT_TRUE(std::isnan(short_turn.tactical_diameter_m));
  EXPECT_TRUE(std::isnan(short_turn.steady_rate_deg_s));
  EXPECT_TRUE(std::isnan(short_turn.steady_radius_m));

  const TurningResponse barely = AnalyseTurning(StraightThenCircle(-1, 60 * kDeg / rate));
  EXPECT_EQ(barely.direction, -1);
  EXPECT_FALSE(barely.reached_90);
  EXPECT_TRUE(std::isnan(barely.advance_m));
  EXPECT_TRUE(std::isnan(barely.transfer_m));

  const TurningResponse no_steady = AnalyseTurning(StraightThenCircle(+1, 530 * kDeg / rate));
  EXPECT_TRUE(no_steady.reached_180);
  EXPECT_NEAR(no_steady.tactical_diameter_m, 2 * kR, kChordTol);
  EXPECT_TRUE(std::isnan(no_steady.steady_rate_deg_s));
}

// odin3dof's turning circle both ways: the analysis of the output agrees with what the maneuver
// measured online (at the first tick past 90 and 180 deg) within one sample's travel.
TEST(TurningResponseTest, SimulatedTurningCircleAgreesWithManeuverReport) {
  const VesselSimulator& sim = FindVessel("odin3dof");
  for (const std::string spec : {"turning:35", "turning:-35"}) {
    auto m = MakeManeuver(spec, sim.Info().actuation, 0.0, 1);
    const SimulationResult r = sim.RunManeuver(*m, sim.Info().default_params, {}, RunOptions{});
    ASSERT_FALSE(r.diverged) << spec;
    const auto& report = r.maneuver.at("report");
    const Dataset& d = r.data;
    double travel = 0.0;
    for (Eigen::Index k = 1; k < d.rows(); ++k)
      travel = std::max(
          travel, std::hypot(d["north"](k) - d["north"](k - 1), d["east"](k) - d["east"](k - 1)));
    const TurningResponse z = AnalyseTurning(d, "psi", "tau_n");
    EXPECT_NEAR(z.execute_s, kLeadInS, 1e-9) << spec;
    EXPECT_EQ(z.direction, spec == "turning:35" ? 1 : -1) << spec;
    ASSERT_TRUE(z.reached_180) << spec;
    EXPECT_NEAR(z.advance_m, report.at("advance_m").get<double>(), travel) << spec;
    EXPECT_NEAR(z.transfer_m, report.at("transfer_m").get<double>(), travel) << spec;
    EXPECT_NEAR(z.tactical_diameter_m, report.at("tactical_diameter_m").get<double>(), travel)
        << spec;
    // The steady turn: the circle sailed over the last turn has the radius U / r at the end.
    ASSERT_FALSE(std::isnan(z.steady_radius_m)) << spec;
    EXPECT_NEAR(z.steady_radius_m, report.at("steady_turning_radius_m").get<double>(),
                1e-3 * z.steady_radius_m)
        << spec;
    const Eigen::Index last = d.rows() - 1;
    EXPECT_NEAR(z.steady_rate_deg_s, std::abs(d["r"](last)) / kDeg, 1e-3 * z.steady_rate_deg_s)
        << spec;
  }
}

// Each missing channel is named, with the data's file.
TEST(TurningResponseTest, MissingChannelIsNamed) {
  for (const std::string channel : {"psi", "delta", "north", "east"}) {
    Dataset d = StraightThenCircle(+1);
    d.metadata()["source"] = "trial.csv";
    d.Remove(channel);
    try {
      AnalyseTurning(d);
      FAIL() << "no InputError without " << channel;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("trial.csv"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("'" + channel + "'"), std::string::npos) << e.what();
    }
  }
}

// A rudder at rest, held at a trim angle, or moving less than 1 deg is not an execution.
TEST(TurningResponseTest, RudderThatNeverMovesIsRefused) {
  Dataset d = StraightThenCircle(+1);
  d.Set("delta", Eigen::VectorXd::Zero(d.rows()));
  EXPECT_THROW(AnalyseTurning(d), InputError);
  d.Set("delta", Eigen::VectorXd::Constant(d.rows(), 5 * kDeg));
  EXPECT_THROW(AnalyseTurning(d), InputError);
  Eigen::VectorXd wobble(d.rows());
  for (Eigen::Index k = 0; k < d.rows(); ++k) wobble(k) = 0.9 * kDeg * std::sin(0.3 * k);
  d.Set("delta", wobble);
  EXPECT_THROW(AnalyseTurning(d), InputError);
}

}  // namespace
}  // namespace usvid
