// An equation model as a steppable system: the identified states, the kinematics the data let it
// integrate, the inputs its equations read, and one RK4 step of it.
#include "metrics/equation_model.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "core/error.h"

namespace usvid {
namespace {

class EquationModelTest : public ::testing::Test {
 protected:
  static bool HasPsi(const std::string& c) { return c == "psi"; }
  static bool HasNothing(const std::string&) { return false; }
};

// A body-velocity model (u, v, r) on data with psi integrates psi, north and east after its
// states; its inputs are the variables that are not integrated, each once, in the order the
// equations first use them (here c, b, a: not sorted), and a name not integrated has index -1.
TEST_F(EquationModelTest, BodyVelocityModelAddsKinematicsAndListsInputsByFirstUse) {
  const nlohmann::json model = {
      {"equations", {{"u", "b - u + 0*c"}, {"v", "a - v + b"}, {"r", "c - r"}}}};
  const EquationModel system(model, HasPsi);
  const std::vector<std::string>& channels = system.Channels();
  ASSERT_EQ(channels.size(), 6u);
  // The states with equations first (in the JSON object's key order, which nlohmann::json keeps
  // sorted: r, u, v), then the kinematic ones.
  std::vector<std::string> states(channels.begin(), channels.begin() + 3);
  std::ranges::sort(states);
  EXPECT_EQ(states, (std::vector<std::string>{"r", "u", "v"}));
  EXPECT_EQ(std::vector<std::string>(channels.begin() + 3, channels.end()),
            (std::vector<std::string>{"psi", "north", "east"}));
  EXPECT_EQ(system.Inputs(), (std::vector<std::string>{"c", "b", "a"}));
  for (size_t i = 0; i < channels.size(); ++i)
    EXPECT_EQ(system.Index(channels[i]), static_cast<int>(i)) << channels[i];
  EXPECT_EQ(system.Index("a"), -1);
  EXPECT_EQ(system.Index("x"), -1);
  // Without psi in the data, no kinematics: only the three states.
  EXPECT_EQ(EquationModel(model, HasNothing).Channels().size(), 3u);
}

// The kinematics of body velocities: psi' = r, north' = u cos psi - v sin psi,
// east' = u sin psi + v cos psi (heading east, surge goes east and sway goes south).
TEST_F(EquationModelTest, BodyKinematicsRotateVelocitiesIntoNorthEast) {
  const nlohmann::json model = {{"equations", {{"u", "0*u"}, {"v", "0*v"}, {"r", "0*r"}}}};
  const EquationModel system(model, HasPsi);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(6), dx(6);
  x(system.Index("u")) = 2.0;
  x(system.Index("v")) = 1.0;
  x(system.Index("r")) = 0.3;
  x(system.Index("psi")) = std::numbers::pi / 2;
  system.Derivative(x, Eigen::VectorXd(0), dx);
  EXPECT_NEAR(dx(system.Index("psi")), 0.3, 1e-15);
  EXPECT_NEAR(dx(system.Index("north")), -1.0, 1e-15);
  EXPECT_NEAR(dx(system.Index("east")), 2.0, 1e-15);
  EXPECT_EQ(dx(system.Index("u")), 0.0);
}

// One step of y' = -a y + b w under a held input is classical RK4: the exact solution
// y_ss + (y0 - y_ss) e^(-a h) with e^z replaced by its Taylor polynomial of degree 4, so it
// differs from the exact solution by at most |z|^5 / 120 (z = -a h, an alternating series) and
// the error falls 32-fold when h halves (local error of order 5).
TEST_F(EquationModelTest, StepOfALinearModelIsRungeKuttaFourAccurate) {
  const double a = 0.5, b = 2.0, w = 0.3, y0 = 1.0, y_ss = b * w / a;
  const EquationModel system({{"equations", {{"y", "-0.5*y + 2*w"}}}}, HasNothing);
  ASSERT_EQ(system.Channels(), std::vector<std::string>{"y"});
  ASSERT_EQ(system.Inputs(), std::vector<std::string>{"w"});
  Eigen::VectorXd u(1);
  u << w;
  double previous_error = 0.0;
  for (const double h : {0.4, 0.2}) {
    Eigen::VectorXd y(1);
    y << y0;
    system.Step(u, h, y);
    const double z = -a * h;
    const double taylor4 = 1 + z + z * z / 2 + z * z * z / 6 + z * z * z * z / 24;
    EXPECT_NEAR(y(0), y_ss + (y0 - y_ss) * taylor4, 1e-15) << h;
    const double exact = y_ss + (y0 - y_ss) * std::exp(z);
    const double error = std::abs(y(0) - exact);
    EXPECT_LE(error, std::abs(y0 - y_ss) * std::pow(std::abs(z), 5) / 120) << h;
    EXPECT_GT(error, 0.0) << h;
    if (previous_error > 0) {
      EXPECT_NEAR(previous_error / error, 32.0, 2.0);
    }
    previous_error = error;
  }
}

// The input delay comes from the model's preprocessing; a model without equations is refused.
TEST_F(EquationModelTest, DelayIsReadAndModelsWithoutEquationsAreRefused) {
  const EquationModel system(
      {{"equations", {{"r", "-r + delta"}}}, {"preprocessing", {{"delay_s", 0.25}}}}, HasPsi);
  EXPECT_EQ(system.DelayS(), 0.25);
  EXPECT_EQ(system.Channels(), (std::vector<std::string>{"r", "psi"}));  // a heading model
  EXPECT_THROW(EquationModel(nlohmann::json::object(), HasPsi), InputError);
  EXPECT_THROW(EquationModel({{"equations", {{"r", "-r +"}}}}, HasPsi), InputError);
}

// A model that also has an equation for a kinematic state (states u, v, r, psi, or U, r, chi:
// `identify --states` accepts any channels) integrates that state by its own equation, once:
// each integrated channel appears once in Channels().
TEST_F(EquationModelTest, KinematicStateWithItsOwnEquationIsIntegratedOnce) {
  const EquationModel body(
      {{"equations", {{"u", "0*u"}, {"v", "0*v"}, {"r", "0*r"}, {"psi", "r"}}}}, HasPsi);
  EXPECT_EQ(std::ranges::count(body.Channels(), std::string("psi")), 1);
  const EquationModel speed({{"equations", {{"U", "0*U"}, {"r", "0*r"}, {"chi", "r"}}}},
                            [](const std::string& c) { return c == "chi"; });
  EXPECT_EQ(std::ranges::count(speed.Channels(), std::string("chi")), 1);
}

}  // namespace
}  // namespace usvid
