// SINDy's weak form (methods/sindy/weak_form.h): integration by parts against a test function
// that vanishes at the window's ends turns x' = theta w into -int phi' x = int phi theta w, so
// the coefficients come from the measured state without differentiating it. The tests check
// that identity, that no window crosses a gap, and what it buys: a velocity measured with the
// transients a GPS filter leaves after each dropout (docs/real-data.md#esso-osaka).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "methods/identify.h"
#include "methods/sindy/sindy.h"
#include "methods/sindy/weak_form.h"
#include "preprocessing/pipeline.h"
#include "tests/support/synthetic_data.h"

namespace usvid {
namespace {

using sindy::LongestWeakWindow;
using sindy::MakeWeakWindows;
using sindy::WeakColumns;
using sindy::WeakTarget;

// A 10 Hz grid from 0 to 60 s, then a dropout, then 80 to 120 s.
Eigen::VectorXd GridWithGap() {
  Eigen::VectorXd t(1002);
  for (Eigen::Index i = 0; i < 601; ++i) t(i) = 0.1 * static_cast<double>(i);
  for (Eigen::Index i = 0; i < 401; ++i) t(601 + i) = 80.0 + 0.1 * static_cast<double>(i);
  return t;
}

// The weak target of x equals the weak column of x' (integration by parts), to the
// quadrature's error; windows lie inside one stretch each, and the stretches list them.
TEST(SindyWeakFormTest, WeakTargetIsTheTestFunctionsMeanOfTheDerivative) {
  const Eigen::VectorXd t = GridWithGap();
  const Eigen::VectorXd x = (0.7 * t.array()).sin() + 0.01 * t.array().square();
  const Eigen::MatrixXd dx = (0.7 * (0.7 * t.array()).cos() + 0.02 * t.array()).matrix();
  const auto w = MakeWeakWindows(t, 51);  // 5 s
  const Eigen::VectorXd lhs = WeakTarget(w, x);
  const Eigen::VectorXd rhs = WeakColumns(w, dx);
  EXPECT_LE((lhs - rhs).cwiseAbs().maxCoeff(), 1e-5 * rhs.cwiseAbs().maxCoeff());
  // phi integrates to one: the weak column of a constant is that constant.
  const Eigen::VectorXd ones = WeakColumns(w, Eigen::MatrixXd::Ones(t.size(), 1));
  EXPECT_NEAR(ones.minCoeff(), 1.0, 1e-12);
  EXPECT_NEAR(ones.maxCoeff(), 1.0, 1e-12);
  ASSERT_EQ(w.stretches.size(), 2u);
  for (const auto& [first, end] : w.windows) {
    EXPECT_EQ(end - first, 51);
    EXPECT_TRUE(end <= 601 || first >= 601) << first << ".." << end;
  }
  // (601 - 51) / 25 + 1 = 23 windows before the gap, (401 - 51) / 25 + 1 = 15 after.
  EXPECT_EQ(w.stretches[0], std::make_pair(Eigen::Index{0}, Eigen::Index{23}));
  EXPECT_EQ(w.stretches[1], std::make_pair(Eigen::Index{23}, Eigen::Index{38}));
}

// The automatic window shortens to leave the windows the folds need, and gives up (0: the
// derivatives) when not even a 5-row window leaves them.
TEST(SindyWeakFormTest, LongestWindowLeavesTheWindowsTheFoldsNeed) {
  const Eigen::VectorXd t = GridWithGap();
  EXPECT_NEAR(LongestWeakWindow(t, 5.0, 38), 5.0, 1e-9);
  const double shorter = LongestWeakWindow(t, 5.0, 50);
  EXPECT_LT(shorter, 5.0);
  EXPECT_GE(MakeWeakWindows(t, std::lround(shorter / 0.1) + 1).windows.size(), 50u);
  EXPECT_EQ(LongestWeakWindow(t, 5.0, 1000), 0.0);
  EXPECT_THROW(MakeWeakWindows(t, 3), InputError);
}

// Surge of a small model ship, u' = -0.05 u + 0.002 n, with the propeller stepped every 60 s,
// measured as a GPS-filtered velocity: after each dropout (every 7.3 s) the filter rings, a
// decaying 0.3 Hz oscillation of 0.1 m/s, as the Esso Osaka logs do. The ringing's slope is
// about 30 times the true acceleration. From the derivatives, no term predicts held-out blocks
// better than none, and SINDy keeps none (the failure on Esso Osaka); 20 s weak-form windows
// average the ringing out and recover both coefficients to 5 %, and the right-hand side on the
// clean record to 10 % (a small constant and u*u come along: the acceleration is small).
TEST(SindyWeakFormTest, RecoversSurgeFromAVelocityThatRingsAfterEachDropout) {
  const Eigen::Index n = 6001;  // 600 s at 10 Hz
  const double dt = 0.1;
  Dataset clean(Eigen::VectorXd::LinSpaced(n, 0.0, dt * static_cast<double>(n - 1)));
  Eigen::VectorXd u(n), rpm(n), ringing(n);
  double state = 0.2;
  for (Eigen::Index i = 0; i < n; ++i) {
    const double t = dt * static_cast<double>(i);
    rpm(i) = 5.0 + 2.5 * static_cast<double>(((i / 600) * 7) % 5);  // 5 .. 15 rps
    u(i) = state;
    for (int k = 0; k < 10; ++k) state += 0.01 * (-0.05 * state + 0.002 * rpm(i));
    const double since = std::fmod(t, 7.3);
    ringing(i) = 0.1 * std::exp(-since / 2.0) * std::sin(2.0 * M_PI * 0.3 * since);
  }
  clean.Set("u", u);
  clean.Set("n", rpm);
  Dataset measured = clean;
  measured.Set("u", u + ringing);
  const PreparedData prep = Preprocess(measured, {"u"}, {"n"}, {});
  sindy::SindyOptions o;
  const sindy::SindyIdentification derivative = IdentifyWithSindy(prep, {"u"}, {"u"}, {"n"}, o);
  EXPECT_TRUE(derivative.details["u"]["terms"].empty()) << derivative.equations["u"];

  o.weak_window_s = 20.0;
  const sindy::SindyIdentification weak = IdentifyWithSindy(prep, {"u"}, {"u"}, {"n"}, o);
  EXPECT_EQ(weak.details["u"]["form"], "weak");
  EXPECT_NEAR(weak.parameters.value("u.u", 0.0), -0.05, 0.0025) << weak.equations["u"];
  EXPECT_NEAR(weak.parameters.value("u.n", 0.0), 0.002, 1e-4) << weak.equations["u"];
  const Eigen::VectorXd truth = -0.05 * u + 0.002 * rpm;
  const Eigen::VectorXd fitted = sindy::PredictWithSindy(weak, "u", clean, {"u"}, {"n"}, {});
  EXPECT_LE((fitted - truth).norm(), 0.1 * truth.norm()) << weak.equations["u"];
}

// Through the method, on a KVLCC2 zig-zag whose u rings as a GPS filter's does (0.3 m/s swings
// after every dropout, against a deceleration of centimetres per second squared): from the
// derivatives every term of u' is cut; the method then regresses the weak form over one hull
// length of travel (320 m at about 7 m/s, shortened to leave 10 windows a fold), says so, and
// returns three equations. Given 0 s (the derivatives), it fails and names u'.
TEST(SindyWeakFormTest, TheMethodFallsBackToTheWeakFormWhenTheDerivativesCutAnEquation) {
  Dataset record = testing::Simulate("kvlcc2", "zigzag:20/20", 900, 0.0, 1);
  Eigen::VectorXd u = record["u"];
  for (Eigen::Index i = 0; i < u.size(); ++i) {
    const double since = std::fmod(record.t()(i), 9.1);
    u(i) += 0.3 * std::exp(-since / 2.0) * std::sin(2.0 * M_PI * 0.3 * since);
  }
  record.Set("u", u);
  IdentifyRequest request;
  request.method = "sindy";
  request.vessel = "kvlcc2";
  std::vector<std::string> lines;
  const nlohmann::json model =
      Identify(record, request, [&](const std::string& line) { lines.push_back(line); });
  for (const char* state : {"u", "v", "r"}) {
    EXPECT_EQ(model.at("sindy").at(state).at("form"), "weak") << state;
    EXPECT_FALSE(model.at("sindy").at(state).at("terms").empty()) << state;
  }
  const double window = model.at("sindy").at("u").at("weak_window_s");
  EXPECT_GT(window, 20.0);
  EXPECT_LT(window, 60.0);
  EXPECT_TRUE(std::ranges::any_of(lines, [](const std::string& l) {
    return l.find("sindy: every term of u' was cut from the derivatives; the weak form") == 0;
  }));

  request.options = {{"weak_window_s", 0.0}};
  try {
    Identify(record, request);
    FAIL() << "the derivatives gave a model";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("every term of u' was cut"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace usvid
