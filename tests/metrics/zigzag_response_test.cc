// Zig-zag figures of merit (ITTC 7.5-04-02-01) read from a record: on a 20/20 zig-zag of a
// first-order Nomoto ship, simulated exactly here, the analysis finds the execution, the
// first turn's direction, the reversals at the rudder's zero crossings and the overshoots beyond
// the threshold; the same record with the ITTC rudder sign (positive to port) gives the same
// figures, since the direction is read from the heading; a test that reversed about a base
// course off the heading at its execute is read about that course; records without a rudder, or
// whose rudder never moves, are refused.
#include "metrics/zigzag_response.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "core/dataset.h"
#include "core/error.h"

namespace usvid {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

struct ZigzagRecord {
  Dataset data;                  // t, psi, delta (positive rudder turns psi positive)
  double execute_s = 0.0;        // when the rudder was first put over
  std::vector<double> reversal;  // times the rudder was reversed (first sample with the new sign)
  std::vector<double> overshoot_deg;  // true excursion beyond B after each reversal
};

// r' = (K delta - r) / T, psi' = r, K = 0.1 1/s, T = 10 s, initial heading psi0 = 0.3 rad, at
// rest. The rudder is held at 0 for a 5 s approach, then put to first_sign * 20 deg; it is
// reversed at the first 0.1 s tick at which psi - base has passed +-20 deg in the direction of
// the turn, base = psi0 + base_offset_deg (a test steered about its ordered course, which the
// ship was that far off at the execute), the third reversal third_late_deg later (a helm
// that reverses at scattered headings). Between ticks the model is solved exactly (the rudder
// is held), and the true overshoots (beyond base +- 20 deg) are taken on a 100 times finer grid
// than the record's.
ZigzagRecord SimulateNomotoZigzag(int first_sign, double duration_s = 300.0,
                                  double base_offset_deg = 0.0, double third_late_deg = 0.0) {
  constexpr double kK = 0.1, kT = 10.0, kDt = 0.1, kLeadIn = 5.0, kPsi0 = 0.3;
  constexpr double kRudder = 20 * kDeg, kB = 20 * kDeg;
  constexpr int kSub = 100;
  const double base = kPsi0 + base_offset_deg * kDeg;
  const int n = static_cast<int>(std::lround(duration_s / kDt)) + 1;
  Eigen::VectorXd t(n), psi(n), delta(n);
  ZigzagRecord rec;
  double p = kPsi0, r = 0.0;
  int sign = 0;  // current rudder direction, 0 during the approach
  std::vector<double> beyond;
  for (int k = 0; k < n; ++k) {
    t(k) = k * kDt;
    if (t(k) >= kLeadIn - 1e-9 && sign == 0) {
      sign = first_sign;
      rec.execute_s = t(k);
    } else if (sign != 0 &&
               sign * (p - base) >= kB + (rec.reversal.size() == 2 ? third_late_deg : 0.0) * kDeg) {
      sign = -sign;
      rec.reversal.push_back(t(k));
      beyond.push_back(-INFINITY);
    }
    psi(k) = p;
    delta(k) = sign * kRudder;
    // Exact solution with delta held over the tick, on a fine grid for the true excursions.
    const double rs = kK * delta(k);  // the steady rate for this rudder
    const double h = kDt / kSub;
    for (int s = 0; s < kSub; ++s) {
      const double decay = std::exp(-h / kT);
      p += rs * h + (r - rs) * kT * (1 - decay);
      r = rs + (r - rs) * decay;
      // After a reversal to `sign`, the heading was turning the other way (-sign).
      if (!beyond.empty() && k + 1 < n) beyond.back() = std::max(beyond.back(), -sign * (p - base));
    }
  }
  for (double b : beyond) rec.overshoot_deg.push_back((b - kB) / kDeg);
  rec.data = Dataset(t);
  rec.data.Set("psi", psi);
  rec.data.Set("delta", delta);
  return rec;
}

void ExpectSameFigures(const ZigzagResponse& z, const ZigzagRecord& rec, int first_turn,
                       const std::string& what, double overshoot_tolerance_deg = 0.05) {
  EXPECT_NEAR(z.execute_s, rec.execute_s, 1e-9) << what;
  EXPECT_EQ(z.first_turn, first_turn) << what;
  ASSERT_EQ(z.reversal_s.size(), rec.reversal.size()) << what;
  ASSERT_EQ(z.overshoot_deg.size(), rec.overshoot_deg.size()) << what;
  for (size_t i = 0; i < rec.reversal.size(); ++i) {
    EXPECT_NEAR(z.reversal_s[i], rec.reversal[i], 1e-9) << what << " reversal " << i;
    EXPECT_NEAR(z.overshoot_deg[i], rec.overshoot_deg[i], overshoot_tolerance_deg)
        << what << " overshoot " << i;
  }
}

TEST(ZigzagResponseTest, NomotoZigzagOvershootsAndReversals) {
  const ZigzagRecord rec = SimulateNomotoZigzag(+1);
  // A real zig-zag: several reversals, overshoots of a few degrees.
  ASSERT_GE(rec.reversal.size(), 4u);
  for (size_t i = 0; i + 1 < rec.overshoot_deg.size(); ++i) {
    EXPECT_GT(rec.overshoot_deg[i], 1.0) << i;
    EXPECT_LT(rec.overshoot_deg[i], 20.0) << i;
  }
  const ZigzagResponse z = AnalyseZigzag(rec.data, 20.0);
  ExpectSameFigures(z, rec, +1, "starboard first");
  // The reversals are the rudder's zero crossings in the record.
  const Eigen::VectorXd& delta = rec.data["delta"];
  for (double ts : z.reversal_s) {
    const Eigen::Index k = std::lround(ts / 0.1);
    ASSERT_GT(k, 0);
    EXPECT_LT(delta(k) * delta(k - 1), 0.0) << "t=" << ts;
  }
}

// Noise on the heading, 2 % of its standard deviation (as `usvid simulate --noise 0.02` adds it,
// 0.3 deg here). The furthest noisy sample lies beyond the true peak by about twice the noise, so
// an overshoot read from the raw heading grows with the noise, and the heading at the execute,
// every overshoot's origin, is one noisy sample. Read from the smoothed heading
// (metrics/criteria_smoothing.h), no overshoot moves by more than 0.1 deg (the last, which the
// record's end cuts short, aside); read from the raw heading, they were up to 0.9 deg high.
TEST(ZigzagResponseTest, NoiseOnTheHeadingDoesNotRaiseTheOvershoots) {
  const ZigzagRecord rec = SimulateNomotoZigzag(+1);
  Eigen::VectorXd psi = rec.data["psi"];
  const double sd = 0.02 * std::sqrt((psi.array() - psi.mean()).square().mean());
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, sd);
  for (double& p : psi) p += noise(rng);
  Dataset noisy = rec.data;
  noisy.Set("psi", psi);

  // The premise: read from the raw samples, the first overshoot would be 0.25 deg high or more.
  const ZigzagResponse clean = AnalyseZigzag(rec.data, 20.0);
  const Eigen::VectorXd& t = rec.data.t();
  const double psi0 = rec.data["psi"](std::lround(clean.execute_s / 0.1));
  double furthest = -INFINITY;
  for (Eigen::Index k = 0; k < t.size(); ++k)
    if (t(k) >= clean.reversal_s[0] && t(k) < clean.reversal_s[1])
      furthest = std::max(furthest, psi(k) - psi0);
  EXPECT_GT(furthest / kDeg - 20.0, rec.overshoot_deg[0] + 0.25);

  const ZigzagResponse z = AnalyseZigzag(noisy, 20.0);
  EXPECT_NEAR(z.execute_s, rec.execute_s, 1e-9);
  ASSERT_EQ(z.overshoot_deg.size(), rec.overshoot_deg.size());
  for (size_t i = 0; i + 1 < rec.overshoot_deg.size(); ++i)
    EXPECT_NEAR(z.overshoot_deg[i], rec.overshoot_deg[i], 0.1) << "overshoot " << i;
}

TEST(ZigzagResponseTest, PortFirstTurnIsReadFromHeading) {
  const ZigzagRecord rec = SimulateNomotoZigzag(-1);
  ASSERT_GE(rec.reversal.size(), 4u);
  ExpectSameFigures(AnalyseZigzag(rec.data, 20.0), rec, -1, "port first");
}

// The ITTC convention (positive rudder turns to port): the same run with delta's sign flipped
// gives identical figures, including first_turn = +1 (psi grows first).
TEST(ZigzagResponseTest, RudderSignConventionDoesNotMatter) {
  const ZigzagRecord rec = SimulateNomotoZigzag(+1);
  const ZigzagResponse starboard_positive = AnalyseZigzag(rec.data, 20.0);
  Dataset flipped = rec.data;
  flipped.Set("delta", -rec.data["delta"]);
  const ZigzagResponse port_positive = AnalyseZigzag(flipped, 20.0);
  ExpectSameFigures(port_positive, rec, +1, "ITTC sign");
  EXPECT_EQ(port_positive.reversal_s, starboard_positive.reversal_s);
  EXPECT_EQ(port_positive.overshoot_deg, starboard_positive.overshoot_deg);
}

// MARIN's KVLCC2 zig-zags reversed about their ordered course, 0.56 and 1.12 deg off the heading
// at the execute. Read about that heading, a symmetric ship's overshoots would differ by about
// twice the offset between the sides. The analysis reads the base course from the headings at
// which the reversals were ordered, and the overshoots about it. Each order falls between two
// samples, 0.2 deg of heading apart at this ship's rate of turn, so the base course is read to
// within 0.1 deg, and so are the overshoots.
TEST(ZigzagResponseTest, OvershootsAreReadAboutTheCourseTheTestReversedAbout) {
  EXPECT_NEAR(AnalyseZigzag(SimulateNomotoZigzag(+1).data, 20.0).base_offset_deg, 0.0, 0.1);
  for (const double offset : {-1.12, 0.56, 3.0}) {
    const ZigzagRecord rec = SimulateNomotoZigzag(+1, 300.0, offset);
    const ZigzagResponse z = AnalyseZigzag(rec.data, 20.0);
    EXPECT_NEAR(z.base_offset_deg, offset, 0.1) << offset;
    ExpectSameFigures(z, rec, +1, "base course " + std::to_string(offset) + " deg", 0.1);
    // The premise: about the heading at the execute, the second overshoot (the other side's)
    // would be read the whole offset off the truth (and the first the other way).
    const double about_execute =
        z.overshoot_deg[1] - (z.first_turn > 0 ? 1 : -1) * z.base_offset_deg;
    EXPECT_GT(std::abs(about_execute - rec.overshoot_deg[1]), 0.9 * std::abs(offset)) << offset;
  }
}

// Reversals ordered at scattered headings (the third 3 deg late, as a helm in a wind's gusts may
// order it) say no base course: their midpoints move with the scatter (by 1.5 deg here). The
// analysis keeps the heading at the execute. (A helm late by as much on every reversal to one
// side is a base course moved half that way, and is read as one: the replay then reverses where
// the record did.)
TEST(ZigzagResponseTest, ScatteredReversalsKeepTheHeadingAtTheExecute) {
  const ZigzagRecord rec = SimulateNomotoZigzag(+1, 300.0, 2.0, 3.0);
  const ZigzagResponse z = AnalyseZigzag(rec.data, 20.0);
  EXPECT_EQ(z.base_offset_deg, 0.0);
  // The same offset with the reversals at one distance from it is read.
  EXPECT_NEAR(AnalyseZigzag(SimulateNomotoZigzag(+1, 300.0, 2.0).data, 20.0).base_offset_deg, 2.0,
              0.1);
}

TEST(ZigzagResponseTest, RudderThatNeverMovesIsRefused) {
  ZigzagRecord rec = SimulateNomotoZigzag(+1);
  rec.data.Set("delta", Eigen::VectorXd::Zero(rec.data.rows()));
  EXPECT_THROW(AnalyseZigzag(rec.data, 20.0), InputError);
  // A constant trim angle is not a rudder execution either.
  rec.data.Set("delta", Eigen::VectorXd::Constant(rec.data.rows(), 5 * kDeg));
  EXPECT_THROW(AnalyseZigzag(rec.data, 20.0), InputError);
}

TEST(ZigzagResponseTest, MissingRudderIsRefused) {
  ZigzagRecord rec = SimulateNomotoZigzag(+1);
  rec.data.metadata()["source"] = "trial.csv";
  rec.data.Remove("delta");
  try {
    AnalyseZigzag(rec.data, 20.0);
    FAIL() << "no InputError without a rudder channel";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("trial.csv"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("delta"), std::string::npos) << e.what();
  }
  // A rudder under another name is found when named.
  ZigzagRecord named = SimulateNomotoZigzag(+1);
  named.data.Set("rudder", named.data["delta"]);
  named.data.Remove("delta");
  EXPECT_THROW(AnalyseZigzag(named.data, 20.0), InputError);
  ExpectSameFigures(AnalyseZigzag(named.data, 20.0, "psi", "rudder"), named, +1, "named rudder");
}

}  // namespace
}  // namespace usvid
