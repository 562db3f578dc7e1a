// Issue 8's acceptance: an effect hidden in data from `usvid simulate` (a seeded random size in
// a realistic range, 0.5 % noise) is named by `usvid diagnose` and its size estimated within
// 10 % of the truth in F.truth.json; clean data give "none"; where the effect is visible
// (nominal held-out fit below 95 % on some channel) the extended model removes at least half of
// the held-out error. Seeds cycle through a zig-zag, random steps and a multisine.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <random>

#include "core/json_file.h"
#include "tests/apps/run_usvid.h"

namespace usvid {
namespace {

using testing::FreshTempDir;
using testing::RunUsvid;
namespace fs = std::filesystem;

struct Range {
  double lo, hi;
  bool either_sign = false;  // biases
  bool reciprocal = false;   // scales: 1/x as likely as x
};

// Realistic sizes on odin3dof (yaw input tau_n [N m], gyro [rad/s], surge force [m/s^2]).
const std::map<std::string, Range>& Ranges() {
  static const std::map<std::string, Range> ranges = {
      {"input_delay", {0.2, 1.5}},
      {"current", {0.2, 1.0}},
      {"actuator_lag", {0.3, 3.0}},
      {"input_bias", {1000, 3000, true}},
      {"sensor_bias", {0.003, 0.01, true}},
      {"inertia", {1.2, 2.0, false, true}},
      {"damping", {1.2, 2.0, false, true}},
      {"saturation", {0.5, 0.9}},
      // 0.25 to 1.5 kN of thrust missing or extra on a 4.9 t hull (cruise thrust 16 kN).
      {"surge_force", {0.05, 0.3, true}},
      {"resistance", {1.3, 2.0, false, true}},
  };
  return ranges;
}

double Size(const std::string& effect, int seed) {
  const Range& r = Ranges().at(effect);
  std::mt19937_64 rng(static_cast<uint64_t>(seed) * 7919 + effect.size());
  double v = std::uniform_real_distribution<double>(r.lo, r.hi)(rng);
  const bool flip = std::uniform_real_distribution<double>(0, 1)(rng) < 0.5;
  if (r.either_sign && flip) v = -v;
  if (r.reciprocal && flip) v = 1.0 / v;
  return std::round(v * 1e4) / 1e4;
}

// The size of an effect as --effect takes it (current: its speed).
double MainSize(const nlohmann::json& parameters) {
  if (parameters.contains("current_north"))
    return std::hypot(parameters.at("current_north").get<double>(),
                      parameters.at("current_east").get<double>());
  return parameters.begin()->get<double>();
}

const char* Maneuver(int seed) {
  static const char* maneuvers[] = {"zigzag:20/20", "random-steps", "multisine"};
  return maneuvers[seed % 3];
}

class HiddenEffectTest : public ::testing::TestWithParam<std::tuple<std::string, int>> {};

TEST_P(HiddenEffectTest, NamesTheEffectAndItsSize) {
  const auto& [effect, seed] = GetParam();
  const fs::path dir = FreshTempDir();
  const std::string data = (dir / "data.csv").string();
  std::string simulate = "simulate --vessel odin3dof --maneuver " + std::string(Maneuver(seed)) +
                         " --duration 200 --noise 0.005 --seed " + std::to_string(seed) +
                         " --out " + data;
  if (effect != "none")
    simulate += " --effect " + effect + "=" + std::to_string(Size(effect, seed));
  const auto sim = RunUsvid(simulate);
  ASSERT_EQ(sim.exit_code, 0) << sim.err;
  const auto r =
      RunUsvid("diagnose --vessel odin3dof --data " + data + " --out " + (dir / "out").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json d = ReadJsonFile((dir / "out" / "diagnosis.json").string());
  const nlohmann::json truth = ReadJsonFile((dir / "data.truth.json").string());
  EXPECT_EQ(d.at("cause"), effect) << d.at("candidates").dump(1);
  if (effect == "none") return;
  const nlohmann::json& candidate = d.at("candidates").at(0);
  ASSERT_EQ(candidate.at("effect"), effect);
  const double true_size = MainSize(truth.at("effects").at(0).at("parameters"));
  const double found = MainSize(candidate.at("parameters"));
  EXPECT_NEAR(found, true_size, 0.1 * std::abs(true_size)) << effect;
  double worst_nominal = 100.0;
  for (const auto& [channel, fit] : d.at("nominal").at("fit_percent").items())
    worst_nominal = std::min(worst_nominal, fit.get<double>());
  if (worst_nominal < 95.0) {
    EXPECT_GE(d.at("gain").at("heldout_error_reduction").get<double>(), 0.5)
        << "nominal worst fit " << worst_nominal;
  }
}

// An effect on one input alone (issue 21): a delay, or a lag, of the yaw moment only. The cause
// is that effect on tau_n, sized within 10 %, and it beats the same effect on every input
// (which delays the surge force too, and the data say it is not).
class OneInputEffectTest : public ::testing::TestWithParam<std::tuple<std::string, double>> {};

TEST_P(OneInputEffectTest, NamesTheEffectItsInputAndSize) {
  const auto& [effect, size] = GetParam();
  const fs::path dir = FreshTempDir();
  const std::string data = (dir / "data.csv").string();
  const auto sim = RunUsvid(
      "simulate --vessel odin3dof --maneuver random-steps --duration 900 --noise 0.005 --seed 11 "
      "--effect " +
      effect + "=" + std::to_string(size) + "@tau_n --out " + data);
  ASSERT_EQ(sim.exit_code, 0) << sim.err;
  const auto r =
      RunUsvid("diagnose --vessel odin3dof --data " + data + " --out " + (dir / "out").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json d = ReadJsonFile((dir / "out" / "diagnosis.json").string());
  ASSERT_EQ(d.at("cause"), effect) << d.at("candidates").dump(1);
  const nlohmann::json& c = d.at("candidates").at(0);
  EXPECT_EQ(c.at("inputs"), nlohmann::json({"tau_n"}));
  EXPECT_NEAR(c.at("parameters").begin()->get<double>(), size, 0.1 * size);
  EXPECT_GE(d.at("gain").at("heldout_error_reduction").get<double>(), 0.5);
  EXPECT_EQ(d.at("extended").at("effect").at("inputs"), nlohmann::json({"tau_n"}));
}

// The high-speed vessel: a 0.5 s delay of the nozzle alone, on top of the jets' own 0.2 s
// transport delay, with the throttle on time (the bucket, held open, is not tried).
TEST(OneInputEffectTestOdinHs, NozzleDelayAlone) {
  const fs::path dir = FreshTempDir();
  const std::string data = (dir / "data.csv").string();
  const auto sim = RunUsvid(
      "simulate --vessel odin-hs --maneuver random-steps --duration 600 --noise 0.005 --seed 3 "
      "--effect input_delay=0.5@nozzle --out " +
      data);
  ASSERT_EQ(sim.exit_code, 0) << sim.err;
  const auto r =
      RunUsvid("diagnose --vessel odin-hs --data " + data + " --out " + (dir / "out").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json d = ReadJsonFile((dir / "out" / "diagnosis.json").string());
  ASSERT_EQ(d.at("cause"), "input_delay") << d.at("candidates").dump(1);
  const nlohmann::json& c = d.at("candidates").at(0);
  EXPECT_EQ(c.at("inputs"), nlohmann::json({"nozzle"}));
  EXPECT_NEAR(c.at("parameters").at("delay_s").get<double>(), 0.5, 0.05);
  EXPECT_GE(d.at("gain").at("heldout_error_reduction").get<double>(), 0.5);
  for (const auto& candidate : d.at("candidates")) {
    if (candidate.contains("inputs")) {
      EXPECT_NE(candidate.at("inputs").at(0), "bucket");
    }
  }
}

// Beyond the catalogue (issue 21): a cross-flow yaw term r' += 0.05 |v| v that odin3dof's model
// lacks. The residual search proposes it, it competes as a missing_term candidate fitted through
// the simulator, and it is the cause (docs/data.md#missing_term); the extended model carries it.
TEST(OneInputEffectTestMissingTerm, CrossFlowYawTermIsTheCause) {
  const fs::path dir = FreshTempDir();
  const std::string data = (dir / "data.csv").string();
  const auto sim = RunUsvid(
      "simulate --vessel odin3dof --maneuver random-steps --duration 900 --noise 0.005 --seed 5 "
      "--effect 'missing_term=0.05:r:abs(v)*v' --out " +
      data);
  ASSERT_EQ(sim.exit_code, 0) << sim.err;
  const std::string out = (dir / "out").string();
  const auto r = RunUsvid("diagnose --vessel odin3dof --data " + data + " --out " + out);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json d = ReadJsonFile(out + "/diagnosis.json");
  ASSERT_EQ(d.at("cause"), "missing_term") << d.at("candidates").dump(1);
  const nlohmann::json& c = d.at("candidates").at(0);
  EXPECT_EQ(c.at("state"), "r");
  EXPECT_EQ(c.at("term"), "abs(v)*v");
  EXPECT_NEAR(c.at("parameters").at("coefficient").get<double>(), 0.05, 0.005);
  EXPECT_GE(d.at("gain").at("heldout_error_reduction").get<double>(), 0.5);
  // The extended model runs the term: evaluate follows the data it was diagnosed on.
  const auto ev = RunUsvid("evaluate --model " + out + "/model.json --data " + data);
  ASSERT_EQ(ev.exit_code, 0) << ev.err;
  EXPECT_GT(nlohmann::json::parse(ev.out).at("r").at("fit_percent").get<double>(), 95.0);
}

// A term outside SINDy's library (products and |x| x): r' += 0.1 |v| r. GP-SR on the residual
// proposes it, and it is the cause. In these data v and r have opposite signs nearly always, so
// |v| r and -v |r| are the same function; either is the term, with its coefficient within 10 %.
TEST(OneInputEffectTestMissingTerm, GpProposesATermOutsideTheLibrary) {
  const fs::path dir = FreshTempDir();
  const std::string data = (dir / "data.csv").string();
  const auto sim = RunUsvid(
      "simulate --vessel odin3dof --maneuver random-steps --duration 900 --noise 0.005 --seed 5 "
      "--effect 'missing_term=0.1:r:abs(v)*r' --out " +
      data);
  ASSERT_EQ(sim.exit_code, 0) << sim.err;
  const std::string out = (dir / "out").string();
  const auto r = RunUsvid("diagnose --vessel odin3dof --threads 2 --data " + data + " --out " + out);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json d = ReadJsonFile(out + "/diagnosis.json");
  ASSERT_EQ(d.at("cause"), "missing_term") << d.at("candidates").dump(1);
  const nlohmann::json& c = d.at("candidates").at(0);
  EXPECT_EQ(c.at("state"), "r");
  const double k = c.at("parameters").at("coefficient").get<double>();
  if (c.at("term") == "abs(r)*v") {
    EXPECT_NEAR(k, -0.1, 0.01);
  } else {
    EXPECT_EQ(c.at("term"), "abs(v)*r");
    EXPECT_NEAR(k, 0.1, 0.01);
  }
  EXPECT_GE(d.at("gain").at("heldout_error_reduction").get<double>(), 0.5);
  bool by_gp = false;
  for (const auto& t : d.at("discovered")) by_gp = by_gp || t.at("method") == "gp";
  EXPECT_TRUE(by_gp) << d.at("discovered").dump(1);
}

// The tanker (issue 21: hidden effects on more vessels than odin3dof). 900 s of zig-zag 20/20
// at 0.5 % noise: nothing hidden, nothing named; a 3 s delay of the rudder is named with its
// size (on the whole vessel or the rudder alone: the propeller's revolutions are held, so the
// two look alike); a cross-flow yaw moment r' += 2e-4 |v| v that the MMG model lacks is the cause
// missing_term, with its coefficient.
class HiddenEffectKvlcc2Test : public ::testing::TestWithParam<std::string> {};

TEST_P(HiddenEffectKvlcc2Test, NamesTheCauseAndItsSize) {
  const std::string& effect = GetParam();
  const fs::path dir = FreshTempDir();
  const std::string data = (dir / "data.csv").string();
  const auto sim = RunUsvid(
      "simulate --vessel kvlcc2 --maneuver zigzag:20/20 --duration 900 --noise 0.005 --seed 7 " +
      (effect.empty() ? std::string() : "--effect '" + effect + "' ") + "--out " + data);
  ASSERT_EQ(sim.exit_code, 0) << sim.err;
  const auto r = RunUsvid("diagnose --vessel kvlcc2 --threads 2 --data " + data + " --out " +
                          (dir / "out").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json d = ReadJsonFile((dir / "out" / "diagnosis.json").string());
  const nlohmann::json& c = d.at("candidates").at(0);
  if (effect.empty()) {
    EXPECT_EQ(d.at("cause"), "none") << c.dump();
    return;
  }
  if (effect.starts_with("input_delay")) {
    ASSERT_EQ(d.at("cause"), "input_delay") << d.at("candidates").dump(1);
    if (c.contains("inputs")) {
      EXPECT_EQ(c.at("inputs"), nlohmann::json({"delta"}));
    }
    EXPECT_NEAR(c.at("parameters").at("delay_s").get<double>(), 3.0, 0.3);
  } else {
    ASSERT_EQ(d.at("cause"), "missing_term") << d.at("candidates").dump(1);
    EXPECT_EQ(c.at("state"), "r");
    EXPECT_EQ(c.at("term"), "abs(v)*v");
    EXPECT_NEAR(c.at("parameters").at("coefficient").get<double>(), 2e-4, 2e-5);
  }
  EXPECT_GE(d.at("gain").at("heldout_error_reduction").get<double>(), 0.5);
}

INSTANTIATE_TEST_SUITE_P(Tanker, HiddenEffectKvlcc2Test,
                         ::testing::Values("", "input_delay=3.0@delta",
                                           "missing_term=2e-4:r:abs(v)*v"),
                         [](const auto& info) {
                           return info.param.empty() ? std::string("none")
                                  : info.param.starts_with("input_delay") ? std::string("rudderdelay")
                                                                          : std::string("missingterm");
                         });

INSTANTIATE_TEST_SUITE_P(YawMomentAlone, OneInputEffectTest,
                         ::testing::Values(std::make_tuple("input_delay", 1.0),
                                           std::make_tuple("actuator_lag", 1.5)),
                         [](const auto& info) {
                           std::string name = std::get<0>(info.param);
                           std::erase(name, '_');
                           return name;
                         });

INSTANTIATE_TEST_SUITE_P(
    Catalogue, HiddenEffectTest,
    ::testing::Combine(::testing::Values("none", "input_delay", "current", "actuator_lag",
                                         "input_bias", "sensor_bias", "inertia", "damping",
                                         "saturation", "surge_force", "resistance"),
                       ::testing::Values(1, 2, 3)),
    [](const auto& info) {
      std::string name =
          std::get<0>(info.param) + "_seed" + std::to_string(std::get<1>(info.param));
      std::erase(name, '_');
      return name;
    });

}  // namespace
}  // namespace usvid
