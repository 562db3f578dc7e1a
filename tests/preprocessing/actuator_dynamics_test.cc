// Actuator dynamics from data (preprocessing/actuator_dynamics.h) on odin-hs runs: the jets see
// each command 0.2 s late (the transport delay) through slew-limited first-order actuators,
//   rpm_cmd = 400 + 1600 throttle,  y' = rate tanh((y_cmd - y) / (tau rate)),
// tau 0.6 s, 600 rev/min/s (rpm); 0.1 s, 0.4363 rad/s (nozzle); 0.1 s, 1 /s (bucket).
// The fit recovers the delay, gain, offset, time constant and, where the record drives an
// actuator into its slew limit, the rate; small steps leave the rate unidentified and say so.
// The identified models reproduce another record's actuator states from its commands alone.
#include "preprocessing/actuator_dynamics.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <random>

#include "core/error.h"
#include "maneuvers/maneuver_factory.h"
#include "sensors/noise.h"
#include "simulation/vessel_simulator.h"
#include "simulators/odin_hs.h"

namespace usvid {
namespace {

using ::testing::HasSubstr;

const std::vector<std::string> kStates = {"rpm", "nozzle_angle", "bucket_position"};

// The true actuator of kWaterjetActuators[i] (odin-hs's defaults).
struct Truth {
  double gain, offset, tau, rate;
};
Truth TrueActuator(int i) {
  const auto& p = OdinHs::kDefaultParams;
  if (i == 0) return {1600.0, 400.0, p[OdinHs::kRpmTau], p[OdinHs::kRpmRate]};
  if (i == 1) return {1.0, 0.0, p[OdinHs::kNozzleTau], p[OdinHs::kNozzleRate]};
  return {1.0, 0.0, p[OdinHs::kBucketTau], p[OdinHs::kBucketRate]};
}

// Random bucket steps in [-1, 1] held 3 to 9 s, open (1) until the first: the stock maneuvers
// hold the bucket open (a fixed input), which leaves nothing to identify.
Eigen::VectorXd BucketSteps(const Eigen::VectorXd& t, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> level(-1.0, 1.0), hold(3.0, 9.0);
  Eigen::VectorXd b(t.size());
  double value = 1.0, next = hold(rng);
  for (Eigen::Index k = 0; k < t.size(); ++k) {
    if (t(k) >= next) value = level(rng), next += hold(rng);
    b(k) = value;
  }
  return b;
}

// 300 s of odin-hs random steps at 20 Hz, the bucket stepped too, the nozzle command scaled by
// nozzle_scale, replayed on the simulator; noise on the actuator states (level x their sd).
Dataset OdinHsRecord(uint64_t seed, double noise, double nozzle_scale = 1.0) {
  const VesselSimulator& sim = FindVessel("odin-hs");
  auto maneuver = MakeManeuver("random-steps", sim.Info().actuation, 300.0, seed);
  Dataset d = sim.RunManeuver(*maneuver, sim.Info().default_params, {}, RunOptions{}).data;
  d.Set("bucket", BucketSteps(d.t(), seed));
  d.Set("nozzle", d["nozzle"] * nozzle_scale);
  d.Set("nozzle_angle", d["nozzle_angle"] * nozzle_scale);  // steady at the first command
  d = sim.RunInputs(d, sim.Info().default_params, {}, RunOptions{}).data;
  AddGaussianNoise(d, kStates, noise, seed);
  return d;
}

// Seed 1 at 0.5 % noise and its three identified actuators, computed once.
struct Identified {
  Dataset data;
  std::vector<ActuatorModel> models;
};
const Identified& SeedOne() {
  static const Identified* identified = [] {
    Dataset d = OdinHsRecord(1, 0.005);
    return new Identified{d, IdentifyWaterjetActuators(d)};
  }();
  return *identified;
}

double Rms(const Eigen::VectorXd& e) { return std::sqrt(e.squaredNorm() / e.size()); }
double Range(const Eigen::VectorXd& v) { return v.maxCoeff() - v.minCoeff(); }

// Largest step of y_cmd over tau rate: far above 1, the actuator slews at its rate limit.
double LargestStepOverLinearRange(const Dataset& d, const std::string& command, int i) {
  const Truth truth = TrueActuator(i);
  const Eigen::VectorXd& u = d[command];
  const Eigen::Index n = u.size();
  const double step = (u.tail(n - 1) - u.head(n - 1)).cwiseAbs().maxCoeff() * truth.gain;
  return step / (truth.tau * truth.rate);
}

TEST(ActuatorDynamicsTest, RecoversDelayGainOffsetTimeConstantAndRateOfEachJetActuator) {
  const Identified& id = SeedOne();
  ASSERT_EQ(id.models.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    const ActuatorModel& m = id.models[i];
    const Truth truth = TrueActuator(i);
    SCOPED_TRACE(m.command + " -> " + m.state);
    EXPECT_EQ(m.command, kWaterjetActuators[i].first);
    EXPECT_EQ(m.state, kWaterjetActuators[i].second);
    EXPECT_NEAR(m.delay_s, OdinHs::kTransportDelay, 0.03);
    EXPECT_NEAR(m.gain, truth.gain, 0.02 * truth.gain);
    // 2 % of the state's span per unit command (the offsets of nozzle and bucket are 0).
    EXPECT_NEAR(m.offset, truth.offset, 0.02 * truth.gain);
    EXPECT_NEAR(m.time_constant_s, truth.tau, 0.25 * truth.tau);
    // Steps beyond twice tau rate slew at the limit (tanh(2) = 0.96): the record shows it.
    // Steps within tau rate hardly leave the linear range: the fit must say it cannot tell.
    // (Seed 1's largest steps are 3.4 (rpm), 20 (nozzle) and 20 (bucket) times tau rate.)
    const double largest = LargestStepOverLinearRange(id.data, m.command, i);
    if (largest > 2.0) {
      ASSERT_TRUE(m.RateLimited());
      EXPECT_NEAR(m.rate_max, truth.rate, 0.1 * truth.rate);
      EXPECT_GT(m.rate_max_sd, 0.0);
    } else if (largest < 1.0) {
      EXPECT_FALSE(m.RateLimited());
      EXPECT_EQ(m.rate_max, INFINITY);
    }
    EXPECT_EQ(m.samples, id.data.rows() - 1);
    EXPECT_GT(m.delay_sd_s, 0.0);
    EXPECT_LT(m.rms_error, 0.01 * Range(id.data[m.state]));  // the 0.5 % noise, not more
  }
}

TEST(ActuatorDynamicsTest, StepsWithinTheLinearRangeLeaveTheRateLimitUnidentified) {
  // Nozzle steps of at most 0.02 x 54 deg = 1.1 deg, within tau rate = 2.5 deg: the actuator
  // never slews, and the record cannot give its rate.
  const Dataset d = OdinHsRecord(4, 0.005, 0.02);
  ASSERT_LT(LargestStepOverLinearRange(d, "nozzle", 1), 1.0);
  const ActuatorModel m = IdentifyActuator(d, "nozzle", "nozzle_angle");
  EXPECT_FALSE(m.RateLimited());
  EXPECT_EQ(m.rate_max, INFINITY);
  EXPECT_TRUE(std::isnan(m.rate_max_sd));
  EXPECT_NEAR(m.delay_s, OdinHs::kTransportDelay, 0.03);
  EXPECT_NEAR(m.gain, 1.0, 0.02);
  EXPECT_NEAR(m.time_constant_s, 0.1, 0.025);
}

TEST(ActuatorDynamicsTest, IdentifiedModelsReproduceAnotherRecordFromItsCommands) {
  const Identified& id = SeedOne();
  const Dataset measured = OdinHsRecord(2, 0.005);
  Dataset commands(measured.t());
  for (const auto& [command, state] : kWaterjetActuators) commands.Set(command, measured[command]);
  SimulateActuators(commands, id.models);
  for (const std::string& state : kStates) {
    const double rms = Rms(commands[state] - measured[state]);
    EXPECT_LT(rms, 0.01 * Range(measured[state])) << state;  // the noise is 0.15 %
  }
}

TEST(ActuatorDynamicsTest, RefusesMissingConstantNonFiniteAndShortRecordsNamingTheChannel) {
  const Eigen::VectorXd t = Eigen::VectorXd::LinSpaced(201, 0.0, 10.0);
  Dataset d(t);
  d.Set("throttle", (t.array() > 5.0).cast<double>().matrix());
  auto message = [](const Dataset& data, const std::string& command, const std::string& state) {
    try {
      IdentifyActuator(data, command, state);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_THAT(message(d, "throttle", "rpm"), HasSubstr("no channel 'rpm'"));
  d.Set("rpm", Eigen::VectorXd::Constant(t.size(), 400.0));
  EXPECT_THAT(message(d, "throttle", "rpm"), HasSubstr("'rpm' is constant"));
  d.Set("rpm", 400.0 + 1600.0 * d["throttle"].array());
  d.Set("bucket", Eigen::VectorXd::Ones(t.size()));
  d.Set("bucket_position", d["rpm"]);
  EXPECT_THAT(message(d, "bucket", "bucket_position"), HasSubstr("'bucket' is constant"));
  Eigen::VectorXd bad = d["rpm"];
  bad(7) = NAN;
  d.Set("rpm_bad", bad);
  EXPECT_THAT(message(d, "throttle", "rpm_bad"), HasSubstr("'rpm_bad' has a non-finite value"));
  Dataset shortened(t.head(10));
  shortened.Set("throttle", d["throttle"].head(10) + Eigen::VectorXd::LinSpaced(10, 0.0, 1.0));
  shortened.Set("rpm", d["rpm"].head(10) + Eigen::VectorXd::LinSpaced(10, 0.0, 1.0));
  EXPECT_THAT(message(shortened, "throttle", "rpm"), HasSubstr("too short: 10 samples of 'rpm'"));
  // 10 s cannot give delays up to 5 s.
  ActuatorOptions long_delays;
  long_delays.max_delay_s = 5.0;
  EXPECT_THROW(IdentifyActuator(d, "throttle", "rpm", long_delays), InputError);
  // The waterjet's three: a record without a nozzle command is refused naming it.
  EXPECT_THAT(
      [&] {
        try {
          IdentifyWaterjetActuators(d);
        } catch (const InputError& e) {
          return std::string(e.what());
        }
        return std::string("no error");
      }(),
      HasSubstr("no channel 'nozzle'"));
}

TEST(ActuatorDynamicsTest, SimulateActuatorsStartsSteadyAndRefusesMissingOrExistingChannels) {
  // A first-order actuator without a rate limit, after its delay: y = 1 - exp(-(t - d) / tau).
  ActuatorModel m;
  m.command = "nozzle";
  m.state = "nozzle_angle";
  m.delay_s = 0.2;
  m.time_constant_s = 0.5;
  const Eigen::VectorXd t = Eigen::VectorXd::LinSpaced(101, 0.0, 5.0);
  Dataset d(t);
  d.Set("nozzle", (t.array() >= 1.0).cast<double>().matrix());
  SimulateActuators(d, {m});
  EXPECT_EQ(d["nozzle_angle"](0), 0.0);                             // steady at the first command
  EXPECT_NEAR(d["nozzle_angle"](24), 0.0, 1e-12);                   // t = 1.2 s: the step arrives
  EXPECT_NEAR(d["nozzle_angle"](44), 1.0 - std::exp(-2.0), 1e-12);  // t = 2.2 s
  // Slew-limited at 0.25 /s: the unit step is 8 times tau rate, and for the first second
  // after it arrives the actuator ramps at the rate limit.
  m.state = "slewed";
  m.rate_max = 0.25;
  SimulateActuators(d, {m});
  EXPECT_NEAR(d["slewed"](34), 0.125, 1e-5);            // t = 1.7 s
  EXPECT_NEAR(d["slewed"](44), 0.25, 1e-5);             // t = 2.2 s
  EXPECT_THROW(SimulateActuators(d, {m}), InputError);  // 'slewed' is there already
  m.state = "other";
  m.command = "throttle";
  try {
    SimulateActuators(d, {m});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("no channel 'throttle'"));
  }
  EXPECT_FALSE(d.Has("other"));
}

TEST(ActuatorDynamicsTest, JsonRoundTripAndAMalformedFieldNamingFileAndField) {
  auto model = [](const std::string& command, const std::string& state, double delay, double gain,
                  double offset, double tau, double rate) {
    ActuatorModel m;
    m.command = command;
    m.state = state;
    m.delay_s = delay;
    m.gain = gain;
    m.offset = offset;
    m.time_constant_s = tau;
    m.rate_max = rate;
    return m;
  };
  ActuatorModel limited = model("throttle", "rpm", 0.2, 1600.0, 400.0, 0.6, 600.0);
  limited.rms_error = 2.5;
  limited.samples = 5999;
  limited.delay_sd_s = 0.001;
  const ActuatorModel linear = model("nozzle", "nozzle_angle", 0.25, 1.0, 0.0, 0.1, INFINITY);
  const nlohmann::json j = ActuatorModelsToJson({limited, linear});
  EXPECT_TRUE(j[1]["rate_max"].is_null());  // not rate-limited: no made-up number
  const std::vector<ActuatorModel> back =
      ActuatorModelsFromJson(nlohmann::json::parse(j.dump()), "a.json");
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[0].command, "throttle");
  EXPECT_EQ(back[0].state, "rpm");
  EXPECT_EQ(back[0].delay_s, 0.2);
  EXPECT_EQ(back[0].gain, 1600.0);
  EXPECT_EQ(back[0].offset, 400.0);
  EXPECT_EQ(back[0].time_constant_s, 0.6);
  EXPECT_EQ(back[0].rate_max, 600.0);
  EXPECT_EQ(back[0].rms_error, 2.5);
  EXPECT_EQ(back[0].samples, 5999);
  EXPECT_EQ(back[0].delay_sd_s, 0.001);
  EXPECT_TRUE(std::isnan(back[0].gain_sd));
  EXPECT_FALSE(back[1].RateLimited());
  EXPECT_EQ(back[1].delay_s, 0.25);

  nlohmann::json bad = j;
  bad[1]["time_constant_s"] = -0.1;
  try {
    ActuatorModelsFromJson(bad, "a.json");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("a.json: actuators[1].time_constant_s: expected"));
  }
  bad = j;
  bad[0]["gain"] = "fast";
  EXPECT_THROW(ActuatorModelsFromJson(bad, "a.json"), InputError);
  EXPECT_THROW(ActuatorModelsFromJson(nlohmann::json::object(), "a.json"), InputError);
}

}  // namespace
}  // namespace usvid
