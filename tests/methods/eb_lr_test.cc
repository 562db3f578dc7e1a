// eb-lr, the Eriksen-Breivik 2-DOF linear regression (methods/eb_lr/eb_lr.h): recovery of the
// eb2dof coefficients from a step grid (issue acceptance: every polynomial coefficient of sigma
// and M within 2 %), steady windows found from the data against the grid's own report, equations
// that parse and evaluate to the fitted model, a run on odin-hs with residuals per regime, and
// bad input.
//
// Noise: the coefficient tests use 0.1 % noise (0.2 % with the output-error mass fit). At 0.5 %
// no estimator meets 2 % on m_U's slope mU1 reliably on any step grid: its Cramer-Rao bound (all
// 11 coefficients from the full record, white noise on U and r) is a standard deviation of 1.07 %
// on stepgrid:5/3 and 1.06-1.18 % on 3/3 to 10/2 grids, since the thrust only steps up and each
// step shows m_U at one speed. Measured over 40 seeds at 0.5 %: mU1 RMS error 1.9 % (equation
// error) and 1.2 % (output error); every other coefficient within 1.4 %.
#include "methods/eb_lr/eb_lr.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

#include "core/error.h"
#include "maneuvers/maneuver_factory.h"
#include "core/expression.h"
#include "preprocessing/pipeline.h"
#include "sensors/noise.h"
#include "simulation/vessel_simulator.h"
#include "simulators/eb2dof.h"

namespace usvid {
namespace {

using eb_lr::EbLrIdentification;
using eb_lr::EbLrOptions;
using eb_lr::IdentifyWithEbLr;
using ::testing::HasSubstr;

// eb2dof's parameter names, in kParamNames order, as eb-lr names them.
constexpr std::array<const char*, Eb2Dof::kParams> kFitNames = {
    "m_U.1",         "m_U.U",       "m_r.1",     "m_r.U",       "sigma_U.U",    "sigma_U.U*U",
    "sigma_U.U*U*U", "sigma_U.r*r", "sigma_r.r", "sigma_r.U*r", "sigma_r.r*r*r"};

class EbLrTest : public ::testing::Test {
 public:
  static SimulationResult Run(const std::string& vessel, const std::string& maneuver) {
    const VesselSimulator& sim = FindVessel(vessel);
    auto m = MakeManeuver(maneuver, sim.Info().actuation, 0.0, 1);
    return sim.RunManeuver(*m, sim.Info().default_params, {}, RunOptions{});
  }
  static Dataset Noisy(Dataset d, double level, uint64_t seed) {
    AddGaussianNoise(d, {"U", "r"}, level, seed);
    return d;
  }
  static const SimulationResult& Eb2DofGrid() {
    static const SimulationResult run = Run("eb2dof", "stepgrid:5/3");
    return run;
  }
  static EbLrIdentification Identify(const Dataset& d, const EbLrOptions& options = {}) {
    return IdentifyWithEbLr(d, "U", "r", "throttle", "nozzle", options);
  }

  // Every eb2dof coefficient within `tolerance` (relative); prints them all.
  static void ExpectCoefficients(const EbLrIdentification& id, double tolerance) {
    for (int i = 0; i < Eb2Dof::kParams; ++i) {
      const double truth = Eb2Dof::kDefaultParams[i];
      const double fit = id.parameters.at(kFitNames[i]).get<double>();
      const double error = (fit - truth) / truth;
      std::cout << Eb2Dof::kParamNames[i] << " (" << kFitNames[i] << "): " << fit << " vs " << truth
                << ", error " << 100 * error << " %\n";
      EXPECT_LE(std::abs(error), tolerance) << Eb2Dof::kParamNames[i];
    }
  }
  // The message of the InputError f throws.
  static std::string Message(const std::function<void()>& f) {
    try {
      f();
    } catch (const InputError& e) {
      return e.what();
    }
    return "(no InputError)";
  }
};

// Issue acceptance: sigma from the steady windows, M from the transients, every polynomial
// coefficient within 2 % of the simulator's (stepgrid:5/3, 0.1 % noise; worst of 100 seeds 1.3 %).
TEST_F(EbLrTest, RecoversEb2DofCoefficientsWithinTwoPercent) {
  ExpectCoefficients(Identify(Noisy(Eb2DofGrid().data, 0.001, 1)), 0.02);
}

// The output-error fit of M keeps 2 % at twice the noise (0.2 %; worst of 100 seeds 1.7 %).
TEST_F(EbLrTest, OutputErrorMassRecoversCoefficientsAtMoreNoise) {
  EbLrOptions options;
  options.output_error_mass = true;
  const EbLrIdentification id = Identify(Noisy(Eb2DofGrid().data, 0.002, 2), options);
  ExpectCoefficients(id, 0.02);
  EXPECT_EQ(id.details["mass_fit"], "output error");
}

// Without noise the regression is consistent: every coefficient within 0.2 %.
TEST_F(EbLrTest, NoiseFreeDataGiveTheCoefficientsClosely) {
  ExpectCoefficients(Identify(Eb2DofGrid().data), 0.002);
}

// The steady windows, found from the data alone, are the grid's steps: one inside each step that
// reached steady state, overlapping the maneuver's own steady stretch (the window_s = 4 s before
// steady_from_s up to end_s), and none elsewhere.
TEST_F(EbLrTest, SteadyWindowsMatchTheGridsSteps) {
  const SimulationResult& run = Eb2DofGrid();
  const EbLrIdentification id = Identify(Noisy(run.data, 0.005, 3));
  const nlohmann::json& steps = run.maneuver["report"]["steps"];
  const nlohmann::json& windows = id.details["steady_windows"];
  int steady_steps = 0, found = 0;
  std::vector<int> owner(windows.size(), -1);
  for (size_t j = 0; j < steps.size(); ++j) {
    if (!steps[j].contains("steady_from_s")) continue;
    ++steady_steps;
    const double start = steps[j]["start_s"], end = steps[j]["end_s"];
    const double steady = steps[j]["steady_from_s"].get<double>() - 4.0;
    bool hit = false;
    for (size_t w = 0; w < windows.size(); ++w) {
      const double a = windows[w]["start_s"], b = windows[w]["end_s"];
      if (a >= start - 1e-9 && b <= end + 1e-9 && b >= steady && a <= end) {
        hit = true;
        owner[w] = static_cast<int>(j);
      }
    }
    found += hit;
  }
  std::cout << found << " of " << steady_steps << " steady steps found, " << windows.size()
            << " windows\n";
  EXPECT_EQ(steady_steps, 35);
  EXPECT_GE(found, steady_steps - 1);
  for (size_t w = 0; w < windows.size(); ++w) EXPECT_GE(owner[w], 0) << windows[w].dump();
}

// The equations parse with core/expression.h and evaluate to the fitted model's derivative
// (tau - sigma(x)) / m(x), which is the simulator's own right-hand side to within 0.5 % RMS.
TEST_F(EbLrTest, EquationsParseAndEvaluateToTheModel) {
  const Dataset& clean = Eb2DofGrid().data;
  const EbLrIdentification id = Identify(Noisy(clean, 0.001, 4));
  auto p = [&](const std::string& name) { return id.parameters.at(name).get<double>(); };
  const Eigen::ArrayXd U = clean["U"].array(), r = clean["r"].array();
  const Eigen::ArrayXd u_dot =
      (clean["throttle"].array() - (p("sigma_U.U") * U + p("sigma_U.U*U") * U * U +
                                    p("sigma_U.U*U*U") * U * U * U + p("sigma_U.r*r") * r * r)) /
      (p("m_U.1") + p("m_U.U") * U);
  const Eigen::ArrayXd r_dot =
      (clean["nozzle"].array() -
       (p("sigma_r.r") * r + p("sigma_r.U*r") * U * r + p("sigma_r.r*r*r") * r * r * r)) /
      (p("m_r.1") + p("m_r.U") * U);
  const Eigen::VectorXd u_eq = Expression::Parse(id.equations["U"], "U").Evaluate(clean);
  const Eigen::VectorXd r_eq = Expression::Parse(id.equations["r"], "r").Evaluate(clean);
  std::cout << "U' = " << id.equations["U"].get<std::string>() << "\n"
            << "r' = " << id.equations["r"].get<std::string>() << "\n";
  EXPECT_LE((u_eq.array() - u_dot).abs().maxCoeff(), 1e-12 * u_dot.abs().maxCoeff());
  EXPECT_LE((r_eq.array() - r_dot).abs().maxCoeff(), 1e-12 * r_dot.abs().maxCoeff());

  Eigen::VectorXd u_true(clean.rows()), r_true(clean.rows());
  for (Eigen::Index k = 0; k < clean.rows(); ++k) {
    const std::array<double, 5> x = {0.0, 0.0, clean["chi"](k), U(k), r(k)};
    const std::array<double, 2> tau = {clean["throttle"](k), clean["nozzle"](k)};
    std::array<double, 5> dx;
    Eb2Dof::Derivative<double>(x.data(), tau.data(), Eb2Dof::kDefaultParams.data(), {}, dx.data());
    u_true(k) = dx[3];
    r_true(k) = dx[4];
  }
  EXPECT_LE((u_eq - u_true).norm() / u_true.norm(), 0.005);
  EXPECT_LE((r_eq - r_true).norm() / r_true.norm(), 0.005);
}

// Residuals of an identification on odin-hs data per Froude regime (displacement Fn < 0.4,
// semi-displacement 0.4-1.1, planing > 1.1): the steady-state (sigma) residuals of the windows in
// input units, and those of the equations against the preprocessed U_dot and r_dot at every
// sample, in m/s^2 and rad/s^2 and as a fraction of the derivative's RMS over the record.
// Returns the RMS sigma_U residual over all windows.
double PrintResidualsPerRegime(const EbLrIdentification& id, const PreparedData& prep) {
  const VesselSimulator& odin = FindVessel("odin-hs");
  const char* kRegimes[] = {"displacement", "semi-displacement", "planing"};
  auto regime = [&](double speed) {
    const double fn = *odin.FroudeNumber(speed);
    return fn < 0.4 ? 0 : fn <= 1.1 ? 1 : 2;
  };
  std::array<std::array<double, 2>, 3> steady_sq{};
  std::array<int, 3> windows{};
  for (const nlohmann::json& w : id.details["steady_windows"]) {
    const int g = regime(w["U"].get<double>());
    steady_sq[g][0] += std::pow(w["residual_U"].get<double>(), 2);
    steady_sq[g][1] += std::pow(w["residual_r"].get<double>(), 2);
    ++windows[g];
  }
  const Eigen::VectorXd u_dot = prep.data["U_dot"], r_dot = prep.data["r_dot"];
  const Eigen::VectorXd u_err = Expression::Parse(id.equations["U"]).Evaluate(prep.data) - u_dot;
  const Eigen::VectorXd r_err = Expression::Parse(id.equations["r"]).Evaluate(prep.data) - r_dot;
  const double u_scale = u_dot.norm() / std::sqrt(u_dot.size());
  const double r_scale = r_dot.norm() / std::sqrt(r_dot.size());
  std::array<std::array<double, 2>, 3> sq{};
  std::array<int, 3> samples{};
  for (Eigen::Index k = 0; k < prep.data.rows(); ++k) {
    const int g = regime(prep.data["U"](k));
    sq[g][0] += u_err(k) * u_err(k);
    sq[g][1] += r_err(k) * r_err(k);
    ++samples[g];
  }
  for (int g = 0; g < 3; ++g) {
    EXPECT_GT(windows[g], 0) << kRegimes[g];
    EXPECT_GT(samples[g], 0) << kRegimes[g];
    const double u_rms = std::sqrt(sq[g][0] / samples[g]), r_rms = std::sqrt(sq[g][1] / samples[g]);
    std::cout << "  " << kRegimes[g] << ": " << windows[g] << " windows, sigma residual RMS "
              << std::sqrt(steady_sq[g][0] / windows[g]) << " (throttle), "
              << std::sqrt(steady_sq[g][1] / windows[g]) << " (nozzle rad); " << samples[g]
              << " samples, U' residual RMS " << u_rms << " m/s^2 (" << u_rms / u_scale
              << " of U_dot's RMS), r' " << r_rms << " rad/s^2 (" << r_rms / r_scale << ")\n";
    EXPECT_TRUE(std::isfinite(u_rms) && std::isfinite(r_rms)) << kRegimes[g];
  }
  return std::sqrt((steady_sq[0][0] + steady_sq[1][0] + steady_sq[2][0]) /
                   (windows[0] + windows[1] + windows[2]));
}

// odin-hs is not the EB model (regime-dependent resistance and yaw damping, jet thrust and yaw
// moment that depend on rpm and speed, actuator lags, a transport delay): the method still runs
// on its step grid (0.5 % noise) and gives finite coefficients; the residuals per Froude regime
// show where the 2-DOF polynomial form fits worst. A constant in sigma_U (idle thrust: throttle 0
// is 400 rpm, not zero thrust) takes most of the steady-state misfit away.
TEST_F(EbLrTest, RunsOnOdinHsAndReportsResidualsPerRegime) {
  const Dataset data = Noisy(Run("odin-hs", "stepgrid:5/3").data, 0.005, 5);
  const PreparedData prep = Preprocess(data, {"U", "r"}, {"throttle", "nozzle"}, {});
  EbLrOptions with_idle;
  with_idle.sigma_speed_basis = eb_lr::ParseBasis("1,U,U^2,U^3,r^2", "sigma_speed_basis");
  double sigma_rms[2];
  int case_index = 0;
  for (const EbLrOptions& options : {EbLrOptions{}, with_idle}) {
    const EbLrIdentification id = Identify(data, options);
    std::cout << "sigma_U on " << eb_lr::BasisText(options.sigma_speed_basis) << ":\n";
    for (const auto& [name, value] : id.parameters.items()) {
      EXPECT_TRUE(std::isfinite(value.get<double>())) << name;
      std::cout << "  " << name << " = " << value.get<double>() << "\n";
    }
    EXPECT_GE(id.details["steady_windows"].size(), 30u);
    sigma_rms[case_index++] = PrintResidualsPerRegime(id, prep);
  }
  EXPECT_LT(sigma_rms[1], 0.5 * sigma_rms[0]);
}

// A thrust that falls with speed (EbLrOptions::thrust_speed_loss): eb2dof's equations with the
// force tau_m (1 - k U), k = 0.02 s/m, integrated (RK4, 0.01 s) under the inputs of eb2dof's own
// step grid. A held command reaches several steady speeds (straight and in the grid's turns), so
// the steady windows separate k tau U from sigma(U, r): k is recovered to 5 %, and without the
// term the steady windows' residual is larger.
TEST_F(EbLrTest, ThrustSpeedLossIsRecoveredFromTheSteadyStates) {
  constexpr double kLoss = 0.02;
  const double* p = Eb2Dof::kDefaultParams.data();  // kFitNames order
  const Dataset& grid = Eb2DofGrid().data;
  const Eigen::VectorXd t = grid.t(), thrust = grid["throttle"], yaw = grid["nozzle"];
  auto f = [&](const Eigen::Vector2d& x, double tau_m, double tau_r) {
    const double U = x(0), r = x(1);
    const double sigma_u = p[4] * U + p[5] * U * U + p[6] * U * U * U + p[7] * r * r;
    const double sigma_r = p[8] * r + p[9] * U * r + p[10] * r * r * r;
    return Eigen::Vector2d((tau_m * (1.0 - kLoss * U) - sigma_u) / (p[0] + p[1] * U),
                           (tau_r - sigma_r) / (p[2] + p[3] * U));
  };
  Dataset data(t);
  Eigen::VectorXd speed(t.size()), rate(t.size());
  Eigen::Vector2d x(grid["U"](0), grid["r"](0));
  for (Eigen::Index k = 0; k < t.size(); ++k) {
    speed(k) = x(0);
    rate(k) = x(1);
    if (k + 1 == t.size()) break;
    const int substeps = std::max(1, static_cast<int>(std::lround((t(k + 1) - t(k)) / 0.01)));
    const double h = (t(k + 1) - t(k)) / substeps;
    for (int n = 0; n < substeps; ++n) {
      const Eigen::Vector2d k1 = f(x, thrust(k), yaw(k)),
                            k2 = f(x + 0.5 * h * k1, thrust(k), yaw(k));
      const Eigen::Vector2d k3 = f(x + 0.5 * h * k2, thrust(k), yaw(k)),
                            k4 = f(x + h * k3, thrust(k), yaw(k));
      x += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    }
  }
  data.Set("U", speed);
  data.Set("r", rate);
  data.Set("throttle", thrust);
  data.Set("nozzle", yaw);
  const Dataset noisy = Noisy(data, 0.001, 3);
  EbLrOptions with_loss;
  with_loss.thrust_loss_channel = "throttle";
  const EbLrIdentification id = Identify(noisy, with_loss);
  const double k = id.parameters.at("sigma_U.throttle*U").get<double>();
  std::cout << "k = " << k << " (truth " << kLoss << ")\n";
  EXPECT_NEAR(k, kLoss, 0.05 * kLoss);
  EXPECT_THAT(id.equations.at("U").get<std::string>(), HasSubstr("*throttle*U"));
  const EbLrIdentification without = Identify(noisy);
  EXPECT_LT(id.details["fit"]["sigma_U"]["rms"].get<double>(),
            without.details["fit"]["sigma_U"]["rms"].get<double>());
}

// Bad input is an InputError naming what is wrong: a missing channel, a constant input, too
// short a record for the basis, a non-uniform grid, an unsampled cell, bad options, a term the
// steady windows cannot separate, a bad basis list.
TEST_F(EbLrTest, BadInputThrows) {
  const Dataset& good = Eb2DofGrid().data;
  EXPECT_THAT(Message([&] { IdentifyWithEbLr(good, "U", "r", "throttle", "rudder", {}); }),
              HasSubstr("'rudder'"));

  Dataset constant = good;
  constant.Set("nozzle", Eigen::VectorXd::Zero(good.rows()));
  EXPECT_THAT(Message([&] { Identify(constant); }), HasSubstr("'nozzle' is constant"));

  Dataset short_run = good;
  std::vector<bool> keep(good.rows());
  for (Eigen::Index k = 0; k < good.rows(); ++k)  // two input steps, three windows
    keep[k] = good.t()(k) >= 290.0 && good.t()(k) < 335.0;
  short_run.KeepRows(keep);
  EXPECT_THAT(Message([&] { Identify(short_run); }), HasSubstr("steady windows"));

  Dataset gap = good;
  std::vector<bool> drop(good.rows(), true);
  drop[100] = false;
  gap.KeepRows(drop);
  EXPECT_THAT(Message([&] { Identify(gap); }), HasSubstr("not uniform"));

  Dataset unsampled = good;
  Eigen::Array<bool, Eigen::Dynamic, 1> mask =
      Eigen::Array<bool, Eigen::Dynamic, 1>::Ones(good.rows());
  mask(10) = false;
  unsampled.Set("r", good["r"], mask);
  EXPECT_THAT(Message([&] { Identify(unsampled); }), HasSubstr("not fully sampled"));

  EbLrOptions bad;
  bad.transient_window_s = 0.0;
  EXPECT_THAT(Message([&] { Identify(good, bad); }), HasSubstr("transient_window_s"));
  bad = {};
  bad.steady.min_window_s = -1.0;
  EXPECT_THAT(Message([&] { Identify(good, bad); }), HasSubstr("min_window_s"));
  bad = {};
  bad.sigma_speed_basis = {{1, 0}, {1, 0}};
  EXPECT_THAT(Message([&] { Identify(good, bad); }), HasSubstr("do not separate"));

  EXPECT_THAT(Message([] { eb_lr::ParseBasis("U,V", "--sigma-speed"); }),
              HasSubstr("unknown factor 'V'"));
  EXPECT_THAT(Message([] { eb_lr::ParseBasis("U^2,U*U", "--sigma-speed"); }),
              HasSubstr("listed twice"));
  EXPECT_THAT(Message([] { eb_lr::ParseBasis("", "--mass-rate"); }), HasSubstr("empty"));
}

// Basis lists read and print as monomials in the caller's channel names, |r| variants included.
TEST_F(EbLrTest, BasisListsReadAsMonomials) {
  const auto basis = eb_lr::ParseBasis("1, U, U^2*r, abs(r)*r, |r|^3", "--basis");
  ASSERT_EQ(basis.size(), 5u);
  EXPECT_EQ(basis[0].Text("U", "r"), "1");
  EXPECT_EQ(basis[2].Text("u", "q"), "u*u*q");
  EXPECT_EQ(basis[3].Text("U", "r"), "abs(r)*r");
  EXPECT_EQ(basis[4].Text("U", "r"), "abs(r)*r*r");
  EXPECT_DOUBLE_EQ(basis[3].Evaluate(2.0, -0.5), -0.25);
  EXPECT_DOUBLE_EQ(basis[4].Evaluate(2.0, -0.5), 0.125);
  EXPECT_EQ(eb_lr::BasisText(basis), "1,U,U^2*r,abs(r)*r,abs(r)*r^2");
  EXPECT_EQ(eb_lr::BasisText(EbLrOptions{}.sigma_speed_basis), "U,U^2,U^3,r^2");
}

}  // namespace
}  // namespace usvid
