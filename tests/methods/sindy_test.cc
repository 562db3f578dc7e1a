// SINDy with STRidge recovers the true equations, checked on held-out data: the identified
// right-hand side against the true one (docs/model.md#msd, docs/model.md#odin3dof), both
// evaluated at the clean states and inputs of a held-out multisine run that the fit never saw.
#include "methods/sindy/sindy.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <map>
#include <set>

#include "core/error.h"
#include "core/expression.h"
#include "importers/froude_scaling.h"
#include "methods/identify.h"
#include "metrics/evaluation.h"
#include "preprocessing/pipeline.h"
#include "simulators/msd.h"
#include "simulators/odin3dof.h"
#include "tests/support/synthetic_data.h"

namespace usvid {
namespace {

using testing::RelativeError;
using testing::Simulate;
using testing::TrueDerivative;

using sindy::IdentifyWithSindy;
using sindy::PredictWithSindy;
using sindy::SindyIdentification;
using sindy::SindyOptions;

const std::vector<std::string> kOdinStates = {"u", "v", "r"};
const std::vector<std::string> kOdinInputs = {"tau_x", "tau_y", "tau_n"};

class SindyTest : public ::testing::Test {
 public:
  static std::set<std::string> TermNames(const std::string& equation) {
    std::set<std::string> names;
    for (const auto& [term, coefficient] : Expression::Parse(equation).Terms()) names.insert(term);
    return names;
  }

  // One odin3dof identification shared by the tests: random steps, 600 s, 0.5 % noise; and a
  // clean held-out multisine run.
  struct OdinCase {
    SindyIdentification id;
    Dataset held;
  };
  static const OdinCase& Odin() {
    static const OdinCase c = [] {
      const Dataset train = Simulate("odin3dof", "random-steps", 600, 0.005, 5);
      const PreparedData prep = Preprocess(train, kOdinStates, kOdinInputs, {});
      OdinCase out{IdentifyWithSindy(prep, kOdinStates, kOdinStates, kOdinInputs, {}),
                   Simulate("odin3dof", "multisine", 300, 0.0, 77)};
      std::cout << out.id.equations.dump(2) << "\n";
      return out;
    }();
    return c;
  }
};

// Issue 6's bar for sindy: its model free-runs held-out multisine runs at 95 % or more. The
// hull is unstable (docs/vessels/odin3dof.md), so a free run's fit depends on the run: the bar
// is on the median over six held-out runs (seeds 1 to 6).
TEST_F(SindyTest, Odin3DofFreeRunsHeldOutMultisineAtNinetyFivePercent) {
  const nlohmann::json model = {
      {"states", kOdinStates}, {"inputs", kOdinInputs}, {"equations", Odin().id.equations}};
  std::map<std::string, std::vector<double>> fits;
  for (uint64_t seed = 1; seed <= 6; ++seed) {
    const Evaluation e = EvaluateModel(model, Simulate("odin3dof", "multisine", 300, 0.0, seed));
    for (const std::string& s : kOdinStates)
      fits[s].push_back(e.metrics.at(s).at("fit_percent").get<double>());
  }
  for (auto& [s, f] : fits) {
    std::sort(f.begin(), f.end());
    EXPECT_GE(0.5 * (f[2] + f[3]), 95.0) << s;
  }
}

// Each of u', v', r' (docs/model.md#odin3dof) within 5 % relative RMS error, held-out multisine.
TEST_F(SindyTest, Odin3DofFromRandomStepsWithinFivePercentOnHeldOutMultisine) {
  const OdinCase& c = Odin();
  for (int i = 0; i < 3; ++i) {
    const std::string& s = kOdinStates[static_cast<size_t>(i)];
    const Eigen::VectorXd truth = TrueDerivative<Odin3Dof>(c.held, 3 + i);
    const double err =
        RelativeError(PredictWithSindy(c.id, s, c.held, kOdinStates, kOdinInputs, {}), truth);
    std::cout << s << "' held-out relative error " << err << "\n";
    EXPECT_LE(err, 0.05) << s;
  }
}

// Sway and yaw have the true structure exactly: v' on u r, v, |v| v, tau_y; r' on v, r, |r| r,
// tau_n (m11 = m22, so the Munk moment u v drops out), with nothing else.
TEST_F(SindyTest, Odin3DofSwayAndYawTermsAreExactlyTheTrueOnes) {
  const OdinCase& c = Odin();
  EXPECT_EQ(TermNames(c.id.equations["v"]), TermNames("-u*r - v - abs(v)*v + tau_y"));
  EXPECT_EQ(TermNames(c.id.equations["r"]), TermNames("-v - r - abs(r)*r + tau_n"));
}

// msd from 1 % noise: v' = -0.2 x - 0.1 v + 0.1 f to 1 % on a held-out multisine run.
TEST_F(SindyTest, MsdRecoveredToOnePercentOnHeldOutData) {
  const Dataset train = Simulate("msd", "random-steps", 300, 0.01, 1);
  const PreparedData prep = Preprocess(train, {"x", "v"}, {"f"}, {});
  const SindyIdentification id = IdentifyWithSindy(prep, {"v"}, {"x", "v"}, {"f"}, {});
  const Dataset held = Simulate("msd", "multisine", 300, 0.0, 999);
  const double err = RelativeError(PredictWithSindy(id, "v", held, {"x", "v"}, {"f"}, {}),
                                   TrueDerivative<Msd>(held, 1));
  std::cout << "v' = " << id.equations["v"].get<std::string>() << "  held-out error " << err
            << "\n";
  EXPECT_LE(err, 0.01);
  EXPECT_EQ(TermNames(id.equations["v"]), TermNames("x + v + f"));
}

// A ship's rudder turns it in proportion to speed: r' = -0.5 r + 0.8 u delta, with u and the
// rudder delta stepped at random (u an input here). The library's input products (issue 38)
// hold u*delta, and SINDy finds exactly the two true terms, to 2 %.
TEST_F(SindyTest, InputProductsFindARudderForceThatGrowsWithSpeed) {
  const int n = 6001;  // 300 s at 20 Hz
  Dataset d(Eigen::VectorXd::LinSpaced(n, 0.0, 300.0));
  Eigen::VectorXd r(n), u(n), delta(n);
  double state = 0.0;
  for (int i = 0; i < n; ++i) {
    u(i) = 1.0 + 0.5 * ((i / 170) % 3);                  // 1, 1.5, 2 m/s
    delta(i) = 0.3 * (((i / 90) * 7919) % 5 - 2) / 2.0;  // -0.3 .. 0.3 rad
    r(i) = state;
    for (int k = 0; k < 50; ++k) state += 0.001 * (-0.5 * state + 0.8 * u(i) * delta(i));
  }
  d.Set("r", r);
  d.Set("U", u);
  d.Set("delta", delta);
  const PreparedData prep = Preprocess(d, {"r"}, {"U", "delta"}, {});
  SindyOptions o;
  o.library.input_products = true;
  const SindyIdentification id = IdentifyWithSindy(prep, {"r"}, {"r"}, {"U", "delta"}, o);
  EXPECT_EQ(TermNames(id.equations["r"]), TermNames("r + U*delta"))
      << id.equations["r"].get<std::string>();
  EXPECT_NEAR(id.parameters["r.r"].get<double>(), -0.5, 0.01);
  EXPECT_NEAR(id.parameters["r.U*delta"].get<double>(), 0.8, 0.016);
}

// Scale-free (issue 38): the same record Froude-scaled from a 3 m model to a 300 m ship
// (lambda 100: time and speed x10, rate / 10) gives the same model in nondimensional form. With
// r_s = r / sqrt(lambda), U_s = U sqrt(lambda) and t_s = t sqrt(lambda), r' = a r + b U delta
// becomes r_s' = (a / sqrt(lambda)) r_s + (b / lambda^1.5) U_s delta: the same terms, and
// coefficients that scale back to the model's. SINDy's thresholds act on unit-RMS columns and
// targets, so the same defaults serve both scales.
TEST_F(SindyTest, AFroudeScaledRecordGivesTheSameNondimensionalModel) {
  const int n = 6001;
  Dataset d(Eigen::VectorXd::LinSpaced(n, 0.0, 300.0));
  Eigen::VectorXd r(n), u(n), delta(n);
  double state = 0.0;
  for (int i = 0; i < n; ++i) {
    u(i) = 0.2 + 0.1 * ((i / 170) % 3);
    delta(i) = 0.3 * (((i / 90) * 7919) % 5 - 2) / 2.0;
    r(i) = state;
    for (int k = 0; k < 50; ++k) state += 0.001 * (-0.1 * state + 0.5 * u(i) * delta(i));
  }
  // 0.1 % noise on the rate, as a gyro's.
  for (int i = 0; i < n; ++i) r(i) += 1e-3 * r.cwiseAbs().maxCoeff() * std::sin(1.7e3 * i);
  d.Set("r", r);
  d.Set("U", u);
  d.Set("delta", delta);
  Dataset ship = d;
  const double lambda = 100.0;
  FroudeScale(ship, lambda);
  SindyOptions o;
  o.library.input_products = true;
  const auto fit = [&](const Dataset& data) {
    return IdentifyWithSindy(Preprocess(data, {"r"}, {"U", "delta"}, {}), {"r"}, {"r"},
                             {"U", "delta"}, o);
  };
  const SindyIdentification model = fit(d), full = fit(ship);
  EXPECT_EQ(TermNames(model.equations["r"]), TermNames(full.equations["r"]))
      << model.equations["r"] << " against " << full.equations["r"];
  for (const auto& [term, power] : {std::pair{"r.r", 0.5}, std::pair{"r.U*delta", 1.5}}) {
    ASSERT_TRUE(model.parameters.contains(term) && full.parameters.contains(term)) << term;
    const double m = model.parameters[term], f = full.parameters[term];
    EXPECT_NEAR(f * std::pow(lambda, power), m, 1e-3 * std::abs(m)) << term;
  }
}

// On noisy data the held-out error picks a threshold above the smallest candidate: the
// selection prunes, rather than keeping the dense least-squares model.
TEST_F(SindyTest, ChosenThresholdIsNotTheSmallestOnNoisyData) {
  const OdinCase& c = Odin();
  const double smallest = sindy::DefaultThresholds().front();
  for (const std::string& s : kOdinStates) {
    const nlohmann::json& d = c.id.details[s];
    EXPECT_GT(d["threshold"].get<double>(), smallest) << s;
    EXPECT_GE(d["threshold"].get<double>(), d["min_error_threshold"].get<double>()) << s;
    EXPECT_LT(d["terms"].size(), d["library"].size()) << s;
  }
}

// Every equation parses with the model.json parser and evaluates to the method's prediction.
TEST_F(SindyTest, EquationsParseAndEvaluateToThePrediction) {
  const OdinCase& c = Odin();
  for (const std::string& s : kOdinStates) {
    const std::string text = c.id.equations[s];
    EXPECT_EQ(text.find("+ -"), std::string::npos) << text;
    const Eigen::VectorXd parsed = Expression::Parse(text).Evaluate(c.held);
    const Eigen::VectorXd own = PredictWithSindy(c.id, s, c.held, kOdinStates, kOdinInputs, {});
    EXPECT_LE((parsed - own).cwiseAbs().maxCoeff(), 1e-12 * own.cwiseAbs().maxCoeff()) << text;
  }
}

// A missing or non-finite channel, too few rows for the folds and bad options are bad input.
TEST_F(SindyTest, BadInputThrows) {
  PreparedData prep;
  prep.data = Dataset(Eigen::VectorXd::LinSpaced(100, 0.0, 9.9));
  prep.data.Set("x", Eigen::VectorXd::LinSpaced(100, 0.0, 1.0));
  prep.data.Set("x_dot", Eigen::VectorXd::Ones(100));
  EXPECT_THROW(IdentifyWithSindy(prep, {"x"}, {"x"}, {"f"}, {}), InputError);
  EXPECT_THROW(IdentifyWithSindy(prep, {"v"}, {"x"}, {}, {}), InputError);
  SindyOptions many_folds;
  many_folds.folds = 11;
  EXPECT_THROW(IdentifyWithSindy(prep, {"x"}, {"x"}, {}, many_folds), InputError);
  Eigen::VectorXd gap = Eigen::VectorXd::Ones(100);
  gap(50) = std::nan("");
  prep.data.Set("g", gap);
  EXPECT_THROW(IdentifyWithSindy(prep, {"x"}, {"x", "g"}, {}, {}), InputError);
  SindyOptions negative;
  negative.thresholds = {0.1, -1.0};
  EXPECT_THROW(IdentifyWithSindy(prep, {"x"}, {"x"}, {}, negative), InputError);
  EXPECT_NO_THROW(IdentifyWithSindy(prep, {"x"}, {"x"}, {}, {}));
}

// A derivative that is pure noise, unrelated to every candidate: no threshold predicts it better
// than nothing, and the regression keeps no term (diagnose's residual search reads that as
// "nothing to propose"). The sindy method turns it into a failed fit that names the state and
// why: never a model "x' = 0".
TEST_F(SindyTest, AnEquationWithNoTermIsAFailedFitThatSaysWhy) {
  const Eigen::Index n = 2000;
  PreparedData prep;
  prep.data = Dataset(Eigen::VectorXd::LinSpaced(n, 0.0, 0.1 * static_cast<double>(n - 1)));
  Eigen::VectorXd x(n), noise(n);
  uint64_t state = 12345;
  for (Eigen::Index i = 0; i < n; ++i) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    noise(i) = static_cast<double>(state >> 11) / 9007199254740992.0 - 0.5;
    x(i) = std::sin(0.01 * static_cast<double>(i));
  }
  prep.data.Set("x", x);
  prep.data.Set("x_dot", noise);
  const SindyIdentification none = IdentifyWithSindy(prep, {"x"}, {"x"}, {}, {});
  EXPECT_TRUE(none.details["x"]["terms"].empty());
  EXPECT_EQ(none.equations["x"], "0");

  prep.data.Set("x_dot", -0.5 * x + 0.01 * noise);
  const SindyIdentification id = IdentifyWithSindy(prep, {"x"}, {"x"}, {}, {});
  EXPECT_NEAR(id.parameters.value("x.x", 0.0), -0.5, 0.01);

  // Through the method: a threshold that cuts everything is named in the error.
  Dataset record = testing::Simulate("odin3dof", "random-steps", 120, 0.005, 1);
  IdentifyRequest request;
  request.method = "sindy";
  request.states = kOdinStates;
  request.inputs = kOdinInputs;
  request.options = {{"threshold", 1e6}, {"weak_window_s", 0.0}};
  try {
    Identify(record, request);
    FAIL() << "a model of 0 was returned";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("sindy: every term of u' was cut: the threshold 1e+06 "
                                         "leaves none"),
              std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("try the weak form"), std::string::npos) << e.what();
  }
  // In the weak form already, the error names its windows and suggests others.
  request.options = {{"threshold", 1e6}, {"weak_window_s", 2.0}};
  try {
    Identify(record, request);
    FAIL() << "a model of 0 was returned";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("this in the weak form over 2 s windows: try other "
                                         "windows"),
              std::string::npos)
        << e.what();
  }
}

// At the defaults (no threshold, no window given), an equation that neither the derivatives nor
// the weak form support by held-out error is not a failed fit: it falls back to the linear
// equation (the state, the inputs, a constant, by least squares), and model.json says so. Here u
// is a random walk that no input drives: its derivative is noise to every candidate.
TEST_F(SindyTest, AtTheDefaultsAnEquationNoTermSupportsFallsBackToTheLinearOne) {
  const Eigen::Index n = 3000;
  Dataset record(Eigen::VectorXd::LinSpaced(n, 0.0, 0.1 * static_cast<double>(n - 1)));
  Eigen::VectorXd u(n), f(n);
  uint64_t state = 777;
  const auto uniform = [&] {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) / 9007199254740992.0 - 0.5;
  };
  double walk = 1.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    walk += 0.01 * uniform();
    u(i) = walk;
    f(i) = (i / 150) % 2 == 0 ? 1.0 : -1.0;
  }
  record.Set("u", u);
  record.Set("f", f);
  IdentifyRequest request;
  request.method = "sindy";
  request.states = {"u"};
  request.inputs = {"f"};
  std::vector<std::string> lines;
  const nlohmann::json model =
      Identify(record, request, [&](const std::string& line) { lines.push_back(line); });
  const nlohmann::json& details = model.at("sindy").at("u");
  EXPECT_EQ(details.at("fallback"), "linear: the held-out folds supported no term of the library");
  EXPECT_EQ(details.at("terms"), (std::vector<std::string>{"1", "u", "f"})) << details.dump();
  EXPECT_NE(model.at("equations").at("u"), "0");
  ASSERT_EQ(model.at("warnings").size(), 1u);
  EXPECT_NE(model.at("warnings")[0].get<std::string>().find("every term of u' was cut"),
            std::string::npos);
  EXPECT_TRUE(std::ranges::any_of(lines, [](const std::string& l) {
    return l == "sindy: warning: every term of u' was cut; its linear equation kept";
  }));
  // A threshold given is the user's to change: the same record then fails, naming u'.
  request.options = {{"threshold", 0.5}};
  EXPECT_THROW(Identify(record, request), InputError);
}

}  // namespace
}  // namespace usvid
