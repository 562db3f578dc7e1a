// A suite's conditions (harness/suite.h, SuiteConditions): effects hidden in every simulated
// record, an unmeasured gusty wind, sensors sampled slower than the output rate, waves on the
// logged motion and sensor dropouts, the same for training and test records, checked on every
// vessel before any fit, echoed so that a resumed run sees them.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.h"
#include "harness/embedded_suites.h"
#include "harness/run_suite.h"
#include "harness/suite.h"

namespace usvid {
namespace {

using ::testing::HasSubstr;

nlohmann::json Base() {
  return {{"name", "conditions"},
          {"vessels", {"odin3dof"}},
          {"train_maneuvers", {"random-steps"}},
          {"test_maneuvers", {"zigzag:20/20"}},
          {"methods", {"nominal"}},
          {"train_seconds", 60},
          {"test_seconds", 60}};
}

TEST(SuiteConditionsTest, AreReadCheckedOnEveryVesselAndEchoed) {
  nlohmann::json j = Base();
  j["effects"] = {"current=0.3:45"};
  j["sensors"] = {"imu=50", "gps=5"};
  const Suite s = ParseSuite(j, "s.json");
  EXPECT_EQ(s.conditions.effects, std::vector<std::string>{"current=0.3:45"});
  EXPECT_EQ(s.conditions.sensors, (std::vector<std::string>{"imu=50", "gps=5"}));
  const nlohmann::json echo = SuiteToJson(s);
  EXPECT_EQ(echo["effects"], j["effects"]);
  EXPECT_EQ(echo["sensors"], j["sensors"]);
  j["waves"] = "0.5:4";
  j["dropouts"] = {"gps=0.1"};
  const nlohmann::json sea = SuiteToJson(ParseSuite(j, "s.json"));
  EXPECT_EQ(sea["waves"], "0.5:4");
  EXPECT_EQ(sea["dropouts"], j["dropouts"]);
  j["gusts"] = "8";
  j["logged"] = {"current", "wind"};
  EXPECT_EQ(SuiteToJson(ParseSuite(j, "s.json"))["logged"], j["logged"]);
  // Without them the echo is what it was before they existed (resumed runs match).
  EXPECT_FALSE(SuiteToJson(ParseSuite(Base(), "s.json")).contains("effects"));

  const std::vector<std::pair<nlohmann::json, std::string>> bad = {
      {{{"effects", {"gust=3"}}}, "s.json: effects: "},
      {{{"effects", {"wind=1"}}}, "odin3dof has no wind model"},
      {{{"effects", "current=0.3"}}, "s.json: effects"},
      {{{"sensors", {"gps=0"}}}, "positive number of Hz"},
      {{{"sensors", {"sonar=5"}}}, "s.json: sensors: odin3dof: --rates 'sonar=5': no group"},
      {{{"waves", "0"}}, "s.json: waves: the significant wave height"},
      {{{"waves", {"1"}}}, "s.json: 'waves' must be a string"},
      {{{"dropouts", {"gps=2"}}}, "s.json: --dropouts 'gps=2'"},
      {{{"gusts", "60"}}, "s.json: gusts: the mean wind speed"},
      {{{"gusts", 8}}, "s.json: 'gusts' must be a string"},
      {{{"dropouts", {"sonar=0.1"}}}, "s.json: sensors: odin3dof: --dropouts 'sonar'"},
      {{{"vessels", {"msd"}}, {"test_maneuvers", {"random-steps"}}, {"waves", "1"}},
       "s.json: sensors: msd: --waves: the record has no"},
      {{{"logged", {"wind"}}}, "s.json: logged: 'wind' logs the gusty wind, and no gusts"},
      {{{"logged", {"current"}}, {"gusts", "8"}}, "s.json: logged: 'current' logs the current"},
      {{{"logged", {"tide"}}}, "s.json: logged: 'tide' is no disturbance"},
  };
  for (const auto& [extra, message] : bad) {
    nlohmann::json b = Base();
    b.update(extra);
    try {
      ParseSuite(b, "s.json");
      ADD_FAILURE() << "accepted " << extra.dump();
    } catch (const InputError& e) {
      EXPECT_THAT(e.what(), HasSubstr(message)) << extra.dump();
    }
  }
}

// A hidden current moves the vessel over ground but not through the water; the GPS at 5 Hz in
// a record at the IMU's 50 Hz fills every tenth row.
TEST(SuiteConditionsTest, SimulatedRecordsCarryTheHiddenEffectsAndTheSensorRates) {
  const Dataset calm = SimulateForSuite("odin3dof", "random-steps", 60, 0.0, 3);
  SuiteConditions current;
  current.effects = {"current=0.5:90"};
  const Dataset drifted = SimulateForSuite("odin3dof", "random-steps", 60, 0.0, 3, current);
  ASSERT_EQ(calm.rows(), drifted.rows());
  const Eigen::Index last = calm.rows() - 1;
  // 0.5 m/s to the east for 60 s: about 30 m further east at the end.
  EXPECT_NEAR(drifted["east"](last) - calm["east"](last), 30.0, 3.0);
  EXPECT_NEAR(drifted["north"](last), calm["north"](last), 3.0);

  SuiteConditions sensors;
  sensors.sensors = {"imu=50", "gps=5"};
  const Dataset logged = SimulateForSuite("odin3dof", "random-steps", 60, 0.005, 3, sensors);
  EXPECT_NEAR(logged.t()(1) - logged.t()(0), 0.02, 1e-12) << "the output rate is the IMU's";
  EXPECT_TRUE(logged.Get("r").FullySampled());
  EXPECT_EQ(logged.Get("north").SampleCount(), 301);
  EXPECT_TRUE(logged.Get("north").Sparse());
  // The same seed gives the same record.
  const Dataset again = SimulateForSuite("odin3dof", "random-steps", 60, 0.005, 3, sensors);
  EXPECT_EQ(logged.Get("north").values().cwiseEqual(again.Get("north").values()).count() +
                (logged.rows() - logged.Get("north").SampleCount()),
            logged.rows());
}

// Waves move the logged motion but not the vessel the maneuver steers: the heading differs from
// the calm record's by the waves' yaw alone, a few degrees; a GPS that drops a fifth of its time
// keeps about four fifths of its samples.
TEST(SuiteConditionsTest, WavesAndDropoutsReachTheRecords) {
  const Dataset calm = SimulateForSuite("odin3dof", "random-steps", 300, 0.0, 5);
  SuiteConditions sea;
  sea.waves = "0.5:4:30";
  sea.sensors = {"gps=5"};
  sea.dropouts = {"gps=0.2"};
  const Dataset rough = SimulateForSuite("odin3dof", "random-steps", 300, 0.0, 5, sea);
  ASSERT_EQ(calm.rows(), rough.rows());
  const double wave_yaw = (rough["psi"] - calm["psi"]).cwiseAbs().maxCoeff();
  EXPECT_GT(wave_yaw, 0.05 * std::numbers::pi / 180);
  EXPECT_LT(wave_yaw, 10 * std::numbers::pi / 180);
  const double kept = static_cast<double>(rough.Get("north").SampleCount()) / 1501.0;
  EXPECT_GT(kept, 0.65);
  EXPECT_LT(kept, 0.93);
}

// The embedded realistic suite (docs/compare.md#realistic) hides the sea and the sensors of a
// trial in every record of both vessels, trains under the autopilot and on random steps, and
// keeps twelve paired cells per vessel and training maneuver for the verdict's tests.
TEST(SuiteConditionsTest, TheRealisticSuiteHasTheSeaAndTheSensorsOfATrial) {
  const Suite s = LoadEmbeddedSuite("realistic");
  EXPECT_EQ(s.name, "realistic");
  EXPECT_EQ(s.vessels, (std::vector<VesselRef>{"odin3dof", "odin-hs"}));
  EXPECT_EQ(s.train_maneuvers, (std::vector<std::string>{"autopilot", "random-steps"}));
  EXPECT_EQ(s.conditions.effects,
            (std::vector<std::string>{"current=0.3", "sensor_bias=0.0017", "saturation=0.8"}));
  EXPECT_EQ(s.conditions.sensors, (std::vector<std::string>{"imu=50", "gps=5"}));
  EXPECT_EQ(s.conditions.dropouts, std::vector<std::string>{"gps=0.05"});
  EXPECT_EQ(s.conditions.waves, "0.3");
  EXPECT_EQ(s.conditions.gusts, "8");
  EXPECT_EQ(s.noise.size() * s.seeds.size(), 12u);
}

// The measured track (docs/compare.md#realistic-measured) is the realistic suite with the wind and
// the current logged, and nothing else changed: its records are the same runs with more
// channels, so the two tracks' cells pair.
TEST(SuiteConditionsTest, TheMeasuredTrackIsTheRealisticSuiteWithTheWindAndTheCurrentLogged) {
  nlohmann::json measured = SuiteToJson(LoadEmbeddedSuite("realistic-measured"));
  nlohmann::json unmeasured = SuiteToJson(LoadEmbeddedSuite("realistic"));
  EXPECT_EQ(measured["name"], "realistic-measured");
  EXPECT_EQ(measured["logged"], nlohmann::json({"wind", "current"}));
  for (nlohmann::json* j : {&measured, &unmeasured}) {
    j->erase("name");
    j->erase("logged");
  }
  EXPECT_EQ(measured, unmeasured);
}

TEST(SuiteConditionsTest, LoggingTheDisturbancesAddsChannelsAndChangesNoMotion) {
  SuiteConditions hidden;
  hidden.effects = {"current=0.4:30"};
  hidden.gusts = "10";
  SuiteConditions logged = hidden;
  logged.logged = {"wind", "current"};
  const Dataset a = SimulateForSuite("odin-hs", "random-steps", 60, 0.0, 4, hidden);
  const Dataset b = SimulateForSuite("odin-hs", "random-steps", 60, 0.0, 4, logged);
  EXPECT_FALSE(a.Has("wind_speed"));
  for (const char* c : {"wind_speed", "wind_direction", "current_u", "current_v"})
    EXPECT_TRUE(b.Has(c)) << c;
  EXPECT_EQ(a["u"], b["u"]);
  EXPECT_EQ(a["psi"], b["psi"]);
  // A 0.4 m/s current, seen in body axes, keeps its speed.
  const Eigen::ArrayXd speed =
      (b["current_u"].array().square() + b["current_v"].array().square()).sqrt();
  EXPECT_NEAR(speed.minCoeff(), 0.4, 1e-9);
  EXPECT_NEAR(speed.maxCoeff(), 0.4, 1e-9);
  // The anemometer reads the 10 m/s wind with the hull's own motion: moving at several m/s,
  // its reading departs from 10 m/s by metres per second somewhere in the run.
  EXPECT_GT((b["wind_speed"].array() - 10.0).abs().maxCoeff(), 1.0);
}

}  // namespace
}  // namespace usvid
