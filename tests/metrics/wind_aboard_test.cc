// A free run meets the logged wind on its own heading (metrics/wind_aboard.h,
// docs/model.md#wind-on-its-own-heading). The record: a hull at rest, its bow swinging gently
// about north (psi = 0.3 (1 - cos 0.2 t)), under a true wind of 2 m/s from the east, which it
// logs from 90 deg - psi. The model turns under the wind's moment alone, r' = -0.01 wind_v. On
// its own heading psi the wind comes from 90 deg - psi, wind_v = -2 cos psi, and r' = 0.02 cos psi
// swings the bow to the east and back, a pendulum between 0 and pi; read as logged, the wind
// stays near the beam, and the heading runs away as about 0.01 t^2.
#include "metrics/wind_aboard.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/dataset.h"
#include "metrics/free_run.h"

namespace usvid {
namespace {

Dataset SwingingAboutNorthUnderAnEastWind() {
  const Eigen::Index rows = 1201;  // 120 s at 10 Hz
  const Eigen::VectorXd t = Eigen::VectorXd::LinSpaced(rows, 0.0, 120.0);
  Dataset d(t);
  for (const char* c : {"u", "v", "north", "east"}) d.Set(c, Eigen::VectorXd::Zero(rows));
  const Eigen::ArrayXd psi = 0.3 * (1.0 - (0.2 * t.array()).cos());
  const Eigen::ArrayXd from = std::numbers::pi / 2 - psi;
  d.Set("psi", psi.matrix());
  d.Set("r", (0.06 * (0.2 * t.array()).sin()).matrix());
  d.Set("wind_speed", Eigen::VectorXd::Constant(rows, 2.0));
  d.Set("wind_direction", from.matrix());
  d.Set("wind_u", (-2.0 * from.cos()).matrix());
  d.Set("wind_v", (-2.0 * from.sin()).matrix());
  return d;
}

const nlohmann::json kTurnedByTheWind = {
    {"equations", {{"u", "0*u"}, {"v", "0*v"}, {"r", "-0.01*wind_v"}}}};

// psi'' = 0.02 cos psi from rest at 0, by RK4 on a fine step: psi at time t.
double Pendulum(double t) {
  double psi = 0.0, r = 0.0;
  const double h = 1e-3;
  auto f = [](double p) { return 0.02 * std::cos(p); };
  for (int k = 0; k < static_cast<int>(std::lround(t / h)); ++k) {
    const double k1p = r, k1r = f(psi);
    const double k2p = r + 0.5 * h * k1r, k2r = f(psi + 0.5 * h * k1p);
    const double k3p = r + 0.5 * h * k2r, k3r = f(psi + 0.5 * h * k2p);
    const double k4p = r + h * k3r, k4r = f(psi + h * k3p);
    psi += h / 6 * (k1p + 2 * k2p + 2 * k3p + k4p);
    r += h / 6 * (k1r + 2 * k2r + 2 * k3r + k4r);
  }
  return psi;
}

TEST(WindAboardTest, AFreeRunTurnsUnderTheWindItsOwnHeadingMeets) {
  const Dataset data = SwingingAboutNorthUnderAnEastWind();
  const FreeRun run = FreeRunModel(kTurnedByTheWind, data);
  ASSERT_FALSE(run.diverged);
  const Eigen::VectorXd& psi = run.simulated["psi"];
  // To the free run's zero-order hold: its inputs are held over each 0.01 s step (0.02 rad
  // off at most when this test was written).
  for (const Eigen::Index k : {100, 300, 600, 900, 1200})
    EXPECT_NEAR(psi(k), Pendulum(data.t()(k)), 0.04) << "at " << data.t()(k) << " s";
  // The bow swings to the east and back, never past south: the wind as logged would have turned
  // it by about 0.01 t^2 = 144 rad by the end.
  EXPECT_GT(psi.maxCoeff(), 2.5);
  EXPECT_LT(psi.maxCoeff(), std::numbers::pi + 0.01);
  // Windows free-run alike (the short-horizon fits).
  const FreeRun windows = FreeRunWindows(kTurnedByTheWind, data, {0, 400});
  EXPECT_NEAR(windows.simulated["psi"](399), psi(399), 1e-12);
  // The second window starts from the record's swing at 40 s, and swings about east too.
  EXPECT_LT(windows.simulated["psi"].maxCoeff(), std::numbers::pi + 0.5);
}

TEST(WindAboardTest, WithoutTheLoggedHeadingOrAnyWindTheWindIsReadAsLogged) {
  Dataset data = SwingingAboutNorthUnderAnEastWind();
  const std::vector<std::string> inputs = {"wind_v"}, channels = {"u", "v", "r", "psi"};
  EXPECT_TRUE(WindAboard(data, inputs, channels).engaged());
  EXPECT_FALSE(WindAboard(data, {"delta"}, channels).engaged());  // the model reads no wind
  EXPECT_FALSE(WindAboard(data, inputs, {"r"}).engaged());        // nor integrates a heading
  // A wind that reads 0 throughout is none logged (a simulation without wind writes 0).
  Dataset calm = data;
  calm.Set("wind_speed", Eigen::VectorXd::Zero(calm.rows()));
  EXPECT_FALSE(WindAboard(calm, inputs, channels).engaged());
  data.Remove("psi");
  EXPECT_FALSE(WindAboard(data, inputs, channels).engaged());
}

}  // namespace
}  // namespace usvid
