// The shooting segment's cost with derivatives over a window of resistance knots
// (methods/fossen_ceres/knot_window_cost.h) is ceres::AutoDiffCostFunction over all 66
// derivatives, bit for bit: the residuals and every Jacobian entry, on a segment that stays
// within one window of knots, on one that accelerates across most of them (several windows),
// on one whose RK4 stages read knots far from its rows' speeds (a trial step with a tiny surge
// mass), and with a parameter block held constant (no Jacobian asked for it).
#include "methods/fossen_ceres/knot_window_cost.h"

#include <gtest/gtest.h>

#include <memory>

#include "methods/fossen_ceres/jet_force_model.h"
#include "methods/fossen_ceres/shooting_segment.h"

namespace usvid::fossen {
namespace {

using Segment = SegmentResidual<JetForceModel>;
constexpr int kParams = JetForceModel::kParams;

struct Case {
  double start_u;    // [m/s]
  double tau_x;      // [N], held
  double m11 = 0.0;  // [kg]; 0: JetForceModel's start
};

// A 10 s segment at 10 Hz under constant forces, measured as some other motion.
std::unique_ptr<Segment> MakeSegment(const Case& c, InputTrack& track) {
  for (int k = 0; k <= 100; ++k) track.Append(0.1 * k, std::array{c.tau_x, 800.0, 3000.0, 0.4});
  auto seg = std::make_unique<Segment>();
  seg->track = &track;
  seg->measured.resize(101, 3);
  for (int k = 0; k <= 100; ++k) {
    seg->times.push_back(0.1 * k);
    seg->measured.row(k) << c.start_u + 0.05 * k, 0.1, 0.02;
  }
  seg->scale = {2.0, 0.5, 0.1};
  seg->continuity = 10.0;
  for (int i = 0; i < kParams; ++i) seg->param_scale[i] = 1.0;
  return seg;
}

// The knots the segment's simulated speeds span at theta.
int KnotsSpanned(const Segment& seg, const std::array<double, kParams>& theta, double u0) {
  std::vector<double> out;
  const double x0[3] = {u0, 0.0, 0.0};
  const size_t rows = seg.Rollout(theta.data(), x0, out);
  const size_t n = out.size() / seg.times.size();
  int lo = JetForceModel::kKnots, hi = -1;
  for (size_t row = 0; row < rows; ++row) {
    const int k = JetForceModel::KnotAt(out[row * n + 3], out[row * n + 4]);
    lo = std::min(lo, k);
    hi = std::max(hi, k);
  }
  return hi - lo + 1;
}

// windows: how many windows of 10 knots the speeds at the rows need (0: not checked).
void ExpectSameAsAutoDiff(const Case& c, bool hold_states, int windows) {
  InputTrack track(JetForceModel::kInputs);
  std::unique_ptr<Segment> seg = MakeSegment(c, track);
  const int m = seg->Residuals();
  std::array<double, kParams> theta = JetForceModel::kStart;
  for (int k = 0; k < JetForceModel::kKnots; ++k)  // a resistance curve with a hump
    theta[JetForceModel::kFirstKnot + k] = 40.0 + 30.0 * std::exp(-0.1 * (k - 12) * (k - 12));
  if (c.m11 > 0) theta[JetForceModel::kM11] = c.m11;
  const std::array<double, 3> x0 = {c.start_u, 0.0, 0.0}, next = {c.start_u + 3.0, 0.2, 0.01};
  const double* parameters[3] = {theta.data(), x0.data(), next.data()};
  if (windows > 0) {
    const int spanned = KnotsSpanned(*seg, theta, c.start_u);
    EXPECT_GT(spanned + 2, 10 * (windows - 1));  // with the knot either side
    EXPECT_LE(spanned + 2, 10 * windows);
  }

  ceres::AutoDiffCostFunction<Segment, ceres::DYNAMIC, kParams, 3, 3> full(new Segment(*seg), m);
  KnotWindowCost<JetForceModel, Segment> windowed(std::move(seg), m);

  std::vector<double> res_full(m), res_win(m);
  std::vector<double> j0_full(m * kParams), j1_full(m * 3), j2_full(m * 3);
  std::vector<double> j0_win(m * kParams, -7.0), j1_win(m * 3, -7.0), j2_win(m * 3, -7.0);
  double* jac_full[3] = {j0_full.data(), hold_states ? nullptr : j1_full.data(), j2_full.data()};
  double* jac_win[3] = {j0_win.data(), hold_states ? nullptr : j1_win.data(), j2_win.data()};
  ASSERT_TRUE(full.Evaluate(parameters, res_full.data(), jac_full));
  ASSERT_TRUE(windowed.Evaluate(parameters, res_win.data(), jac_win));
  EXPECT_EQ(res_win, res_full);
  EXPECT_EQ(j0_win, j0_full);
  if (!hold_states) {
    EXPECT_EQ(j1_win, j1_full);
  }
  EXPECT_EQ(j2_win, j2_full);

  // Residuals alone: both evaluate the functor in doubles.
  std::vector<double> res_only_full(m), res_only_win(m);
  ASSERT_TRUE(full.Evaluate(parameters, res_only_full.data(), nullptr));
  ASSERT_TRUE(windowed.Evaluate(parameters, res_only_win.data(), nullptr));
  EXPECT_EQ(res_only_win, res_only_full);
}

TEST(KnotWindowCostTest, OneWindowIsAutoDiffBitForBit) {
  ExpectSameAsAutoDiff({4.0, 1500.0}, false, 1);  // about 4 to 5 m/s: one window of knots
}

TEST(KnotWindowCostTest, SeveralWindowsAreAutoDiffBitForBit) {
  ExpectSameAsAutoDiff({1.0, 3e4}, false, 5);  // from 1 m/s past the last knot (20 m/s)
}

// What a trial step of the solver can ask: a surge mass of 100 kg braked by 30 kN at 8 m/s. The
// RK4 stages between two rows reach speeds far from either row's (a window from the rows' speeds
// and a knot either side missed some knots the stages read): the knots read between the rows
// count too.
TEST(KnotWindowCostTest, KnotsReadBetweenRowsAreInTheWindows) {
  ExpectSameAsAutoDiff({8.0, -3e4, 100.0}, false, 0);
}

TEST(KnotWindowCostTest, HeldBlockGetsNoJacobian) { ExpectSameAsAutoDiff({1.0, 3e4}, true, 5); }

}  // namespace
}  // namespace usvid::fossen
