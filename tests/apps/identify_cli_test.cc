// `usvid identify --method gp` as a user runs it: model.json with the documented fields and
// equations, the same equations at 1 and 2 threads, bad options refused with exit code 2.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "core/csv_dataset.h"
#include "core/json_file.h"
#include "core/expression.h"
#include "methods/regime_features.h"
#include "tests/apps/run_usvid.h"

namespace usvid {
namespace {

using testing::FreshTempDir;
using ::testing::HasSubstr;
using testing::RunUsvid;
using testing::WriteText;
namespace fs = std::filesystem;

class IdentifyCliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = FreshTempDir();
    data_ = (dir_ / "msd.csv").string();
    ASSERT_EQ(RunUsvid("simulate --vessel msd --maneuver random-steps --duration 300 --noise 0.01 "
                       "--seed 3 --out " +
                       data_)
                  .exit_code,
              0);
  }
  fs::path dir_;
  std::string data_;
};

// docs/data.md#modeljson: method, vessel, states, inputs, parameters, train, seed, equations.
TEST_F(IdentifyCliTest, WritesModelJsonWithEquations) {
  const auto out = (dir_ / "model.json").string();
  const auto r = RunUsvid("identify --method gp --vessel msd --data " + data_ +
                          " --population 300 --generations 20 --ols-threshold 0.01 --out " + out);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("generation 0"));
  const nlohmann::json m = ReadJsonFile(out);
  for (const char* key :
       {"method", "vessel", "states", "inputs", "parameters", "train", "seed", "equations"})
    EXPECT_TRUE(m.contains(key)) << key;
  EXPECT_EQ(m.at("states"), nlohmann::json({"v"}));  // x follows from the kinematics
  EXPECT_EQ(m.at("inputs"), nlohmann::json({"f"}));
  const std::string eq = m.at("equations").at("v");
  EXPECT_THAT(eq, HasSubstr("x"));
  EXPECT_THAT(eq, HasSubstr("f"));
  EXPECT_FALSE(m.at("gp").at("equations").at("v").at("pareto").empty());
  // The equation is in the equation syntax: it parses and evaluates on the data's channels.
  const Expression e = Expression::Parse(eq, "model.json");
  const Eigen::VectorXd values = e.Evaluate(ReadDatasetCsv(data_));
  EXPECT_TRUE(values.allFinite());
}

// The same seed gives the same equations at 1 and at 2 threads.
TEST_F(IdentifyCliTest, SameSeedSameEquationsAtAnyThreadCount) {
  const std::string common = "identify --method gp --vessel msd --data " + data_ +
                             " --population 200 --generations 8 --seed 11 --operators +,-,*,abs";
  const auto one = (dir_ / "one.json").string(), two = (dir_ / "two.json").string();
  ASSERT_EQ(RunUsvid(common + " --threads 1 --out " + one).exit_code, 0);
  ASSERT_EQ(RunUsvid(common + " --threads 2 --out " + two).exit_code, 0);
  EXPECT_EQ(ReadJsonFile(one).at("equations"), ReadJsonFile(two).at("equations"));
  EXPECT_EQ(ReadJsonFile(one).at("parameters"), ReadJsonFile(two).at("parameters"));
}

// --delay auto: the report's scan, made right, finds the msd's 0.5 s input delay and the
// model says so.
TEST_F(IdentifyCliTest, FindsTheInputDelay) {
  const auto late = (dir_ / "late.csv").string(), out = (dir_ / "late.json").string();
  ASSERT_EQ(RunUsvid("simulate --vessel msd --maneuver random-steps --duration 300 --rate 100 "
                     "--noise 0.01 --effect input_delay=0.5 --out " +
                     late)
                .exit_code,
            0);
  const auto r = RunUsvid("identify --method gp --vessel msd --data " + late +
                          " --delay auto --population 100 --generations 5 --out " + out);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NEAR(ReadJsonFile(out).at("preprocessing").at("delay_s").get<double>(), 0.5, 0.01);
}

// The defaults choose the number of terms by held-out error and the model by simulation, and
// model.json says which candidate was chosen and why; --preset report is the reference
// report's Table 3.1 (population 2000, crossover 0.9, mutation 0.1, OLS threshold 0.05, max
// depth 6, + - *) with nothing added.
TEST_F(IdentifyCliTest, DefaultsSayWhichCandidateAndPresetReportIsTableThreeOne) {
  const auto ours = (dir_ / "default.json").string(), report = (dir_ / "report.json").string();
  const std::string common = "identify --method gp --vessel msd --data " + data_ +
                             " --population 200 --generations 8 --out ";
  ASSERT_EQ(RunUsvid(common + ours).exit_code, 0);
  const nlohmann::json d = ReadJsonFile(ours).at("gp");
  EXPECT_EQ(d.at("term_selection"), "held-out blocks");
  EXPECT_TRUE(d.at("ols_threshold").is_null());
  const nlohmann::json& selection = d.at("equations").at("v").at("selection");
  EXPECT_THAT(selection.at("reason").get<std::string>(), HasSubstr("short-horizon simulation"));
  EXPECT_FALSE(selection.at("candidates").empty());
  EXPECT_FALSE(selection.at("free_run_diverged").get<bool>());

  ASSERT_EQ(RunUsvid("identify --method gp --vessel msd --data " + data_ + " --preset report " +
                     "--generations 3 --out " + report)
                .exit_code,
            0);
  const nlohmann::json r = ReadJsonFile(report).at("gp");
  EXPECT_EQ(r.at("population"), 2000);
  EXPECT_EQ(r.at("crossover"), 0.9);
  EXPECT_EQ(r.at("mutation"), 0.1);
  EXPECT_EQ(r.at("ols_threshold"), 0.05);
  EXPECT_EQ(r.at("max_depth"), 6);
  EXPECT_EQ(r.at("operators"), "+,-,*");
  EXPECT_EQ(r.at("constant_iterations"), 0);
  EXPECT_EQ(r.at("restarts"), 0);
  EXPECT_EQ(r.at("validation_fraction"), 0.0);
  EXPECT_THAT(r.at("equations").at("v").at("selection").at("reason").get<std::string>(),
              HasSubstr("no validation part"));
}

// --forces waterjet: a model identified on the jets' forces (derived from rpm, nozzle angle and
// bucket) says so, and `evaluate` drives its free run with the same forces from the test log.
TEST_F(IdentifyCliTest, WaterjetForcesFromTheJetStatesDriveIdentifyAndEvaluate) {
  const auto train = (dir_ / "hs.csv").string(), test = (dir_ / "hs_test.csv").string();
  const auto model = (dir_ / "hs.json").string();
  for (const auto& [file, seed] : {std::pair{train, 1}, std::pair{test, 2}})
    ASSERT_EQ(RunUsvid("simulate --vessel odin-hs --maneuver random-steps --duration 120 --seed " +
                       std::to_string(seed) + " --out " + file)
                  .exit_code,
              0);
  const auto r = RunUsvid("identify --method gp --vessel odin-hs --data " + train +
                          " --states u,v,r --inputs tau_x,tau_y,tau_n --forces waterjet "
                          "--population 200 --generations 5 --out " +
                          model);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json m = ReadJsonFile(model);
  EXPECT_EQ(m.at("preprocessing").at("forces"), "waterjet");
  EXPECT_EQ(m.at("inputs"), nlohmann::json({"tau_x", "tau_y", "tau_n"}));
  const auto e = RunUsvid("evaluate --model " + model + " --data " + test + " --out " +
                          (dir_ / "ev").string());
  ASSERT_EQ(e.exit_code, 0) << e.err;
  const nlohmann::json metrics = ReadJsonFile((dir_ / "ev" / "metrics.json").string());
  for (const char* c : {"u", "v", "r"})
    EXPECT_TRUE(metrics.at("channels").at(c).at("fit_percent").is_number()) << c;
}

// fossen-ceres through --forces waterjet with the vessel's defaults: the inputs are the map's
// forces and jet flow, and the model is the high-speed form (speed-dependent damping).
TEST_F(IdentifyCliTest, FossenOnTheJetForcesIsTheHighSpeedForm) {
  const auto train = (dir_ / "hs_f.csv").string(), model = (dir_ / "hs_f.json").string();
  ASSERT_EQ(RunUsvid("simulate --vessel odin-hs --maneuver random-steps --duration 60 --seed 3 "
                     "--out " +
                     train)
                .exit_code,
            0);
  const auto r = RunUsvid(
      "identify --method fossen-ceres --vessel odin-hs --forces waterjet "
      "--rate 5 --fit equation --data " +
      train + " --out " + model);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json m = ReadJsonFile(model);
  EXPECT_EQ(m.at("inputs"), nlohmann::json({"tau_x", "tau_y", "tau_n", "jet_flow"}));
  EXPECT_EQ(m.at("fossen").at("model"), "fossen-jet");
  EXPECT_TRUE(m.at("parameters").contains("c10"));  // c(U) at 10 m/s
}

// SINDy with the regime features (issue 19): on odin-hs random steps, which cross the
// displacement and planing boundaries, --features auto adds Fn and the hinges abs(Fn - k) to
// its library; the surge equation uses them (the resistance hump), model.json lists them, and
// the free run on another seed recomputes them from the simulated u and v. Without them the
// surge equation has no curve with a hump and its held-out fit is lower.
TEST_F(IdentifyCliTest, SindyTakesTheRegimeFeaturesAndAFreeRunRecomputesThem) {
  const auto train = (dir_ / "hs_s.csv").string(), test = (dir_ / "hs_s_test.csv").string();
  for (const auto& [file, seed] : {std::pair{train, 1}, std::pair{test, 1001}})
    ASSERT_EQ(RunUsvid("simulate --vessel odin-hs --maneuver random-steps --duration 300 "
                       "--noise 0.005 --seed " +
                       std::to_string(seed) + " --out " + file)
                  .exit_code,
              0);
  auto surge_fit = [&](const std::string& features) {
    const auto model = (dir_ / ("hs_s_" + features + ".json")).string();
    const auto r = RunUsvid("identify --method sindy --vessel odin-hs --forces waterjet --data " +
                            train + " --features " + features + " --out " + model);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    const nlohmann::json m = ReadJsonFile(model);
    EXPECT_EQ(m.at("sindy").at("features").size(),
              features == "auto" ? 1u + kSindyFroudeHinges : 0u);
    EXPECT_EQ(m.at("inputs"), nlohmann::json({"tau_x", "tau_y", "tau_n", "jet_flow"}));
    if (features == "auto") {
      EXPECT_THAT(m.at("equations").at("u").get<std::string>(), HasSubstr("(abs(sqrt(u*u + v*v)/"));
    }
    const auto ev = (dir_ / ("ev_s_" + features)).string();
    const auto e = RunUsvid("evaluate --model " + model + " --data " + test + " --out " + ev);
    EXPECT_EQ(e.exit_code, 0) << e.err;
    return ReadJsonFile(ev + "/metrics.json")
        .at("channels")
        .at("u")
        .at("fit_percent")
        .get<double>();
  };
  const double with = surge_fit("auto"), without = surge_fit("none");
  EXPECT_GT(with, 80.0);
  EXPECT_GT(with, without + 5.0) << without;
}

// GP with the rudder's inflow (docs/baselines.md#the-rudders-inflow): on a KVLCC2 zig-zag, whose
// propeller channel is rev, --rudder-inflow adds delta times |u| u, u rev+ and rev+ rev+ to the
// variables its trees are built of, and model.json lists each with its expression, so that a
// free run on another record recomputes them from the simulated u. Without the flag it adds
// none, and on a waterjet (a nozzle, not a rudder) none either.
TEST_F(IdentifyCliTest, GpTakesTheRudderInflowAndAFreeRunRecomputesIt) {
  const auto train = (dir_ / "kv_g.csv").string(), test = (dir_ / "kv_g_test.csv").string();
  ASSERT_EQ(
      RunUsvid("simulate --vessel kvlcc2 --maneuver zigzag:20/20 --duration 300 --out " + train)
          .exit_code,
      0);
  ASSERT_EQ(
      RunUsvid("simulate --vessel kvlcc2 --maneuver zigzag:10/10 --duration 300 --out " + test)
          .exit_code,
      0);
  int fits = 0;
  auto features = [&](const std::string& vessel, const std::string& data, const std::string& flag) {
    const auto model = (dir_ / ("g_" + std::to_string(++fits) + ".json")).string();
    const auto r =
        RunUsvid("identify --method gp --vessel " + vessel + " --data " + data +
                 " --population 100 --generations 3 --seed 1 " + flag + " --out " + model);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return std::pair{model, ReadJsonFile(model).at("gp").at("features")};
  };
  const auto [model, with] = features("kvlcc2", train, "--rudder-inflow");
  EXPECT_EQ(with, nlohmann::json({{"delta_uu", "abs(u)*u*delta"},
                                  {"delta_un", "u*(rev+abs(rev))*delta"},
                                  {"delta_nn", "(rev+abs(rev))*(rev+abs(rev))*delta"}}));
  const auto e = RunUsvid("evaluate --model " + model + " --data " + test + " --out " +
                          (dir_ / "ev_g").string());
  EXPECT_EQ(e.exit_code, 0) << e.err;
  EXPECT_TRUE(features("kvlcc2", train, "").second.empty());
  const auto jet = (dir_ / "hs_g.csv").string();
  ASSERT_EQ(
      RunUsvid("simulate --vessel odin-hs --maneuver zigzag --duration 60 --out " + jet).exit_code,
      0);
  const nlohmann::json on_a_jet =
      features("odin-hs", jet, "--rudder-inflow --features none").second;
  EXPECT_TRUE(on_a_jet.empty()) << "a waterjet took " << on_a_jet.dump();
}

// GP's yaw constant from the training zig-zag (--yaw-bias zigzag,
// metrics/yaw_bias_calibration.h): model.json reports the zig-zag it was read from, the
// constant before and after and the overshoot errors that chose it, and stderr says what was
// done. Without the flag the model has no calibration; without a vessel it says why none ran.
TEST_F(IdentifyCliTest, GpSetsTheYawConstantFromTheTrainingZigzagWhenAsked) {
  const auto train = (dir_ / "kv_z.csv").string();
  ASSERT_EQ(
      RunUsvid("simulate --vessel kvlcc2 --maneuver zigzag:-20/20 --duration 600 --out " + train)
          .exit_code,
      0);
  const std::string common =
      "identify --method gp --data " + train + " --population 100 --generations 3 --seed 1 ";
  const auto asked = (dir_ / "z_asked.json").string(), not_asked = (dir_ / "z_not.json").string();
  const auto r = RunUsvid(common + "--vessel kvlcc2 --yaw-bias zigzag --out " + asked);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("r's constant from the training zig-zags' overshoots"), std::string::npos)
      << r.err;
  const nlohmann::json report = ReadJsonFile(asked).at("calibration").at("yaw_bias");
  EXPECT_EQ(report.at("maneuvers"), nlohmann::json::array({"zigzag:-20/20"})) << report.dump();
  EXPECT_EQ(report.at("overshoot_errors_before").size(), 2u) << report.dump();
  if (report.at("applied").get<bool>()) {
    EXPECT_NE(report.at("constant_after"), report.at("constant_before"));
  }
  ASSERT_EQ(RunUsvid(common + "--vessel kvlcc2 --out " + not_asked).exit_code, 0);
  EXPECT_FALSE(ReadJsonFile(not_asked).contains("calibration"));
  const auto vesselless = (dir_ / "z_no_vessel.json").string();
  ASSERT_EQ(
      RunUsvid(common + "--states u,v,r --inputs delta,rev --yaw-bias zigzag --out " + vesselless)
          .exit_code,
      0);
  EXPECT_EQ(ReadJsonFile(vesselless).at("calibration").at("yaw_bias").at("reason"),
            "no vessel to take the replay's rudder from");
}

// A log of the commands alone (issue 19): `usvid actuators` identifies throttle -> rpm and
// nozzle -> nozzle_angle (delay 0.2 s, time constants 0.6 and 0.1 s) on a log that records
// both, leaves the held bucket out, and `--actuators` then rebuilds the jets' forces of a log
// without rpm and nozzle_angle to within 1 % of those from the measured states. Without
// --actuators, the map refuses that log naming the channels it lacks.
TEST_F(IdentifyCliTest, ActuatorModelsDriveTheJetForcesOfALogOfCommandsAlone) {
  const auto full = (dir_ / "hs_full.csv").string(), commands = (dir_ / "hs_cmd.csv").string(),
             actuators = (dir_ / "actuators.json").string();
  ASSERT_EQ(RunUsvid("simulate --vessel odin-hs --maneuver random-steps --duration 120 --seed 4 "
                     "--out " +
                     full)
                .exit_code,
            0);
  const auto a = RunUsvid("actuators --data " + full + " --out " + actuators);
  ASSERT_EQ(a.exit_code, 0) << a.err;
  EXPECT_THAT(a.err, HasSubstr("bucket -> bucket_position: the command is held"));
  const nlohmann::json models = ReadJsonFile(actuators).at("actuators");
  ASSERT_EQ(models.size(), 2u);
  EXPECT_EQ(models[0].at("state"), "rpm");
  EXPECT_NEAR(models[0].at("delay_s").get<double>(), 0.2, 0.01);
  EXPECT_NEAR(models[0].at("time_constant_s").get<double>(), 0.6, 0.03);
  EXPECT_NEAR(models[1].at("time_constant_s").get<double>(), 0.1, 0.01);

  Dataset d = ReadDatasetCsv(full);
  d.Remove("rpm");
  d.Remove("nozzle_angle");
  WriteDatasetCsv(commands, d);
  const std::string pre = " --states u,v,r --inputs tau_x,tau_y,tau_n --forces waterjet --out ";
  const auto refused = RunUsvid("preprocess --data " + commands + pre + (dir_ / "x.csv").string());
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_THAT(refused.err, HasSubstr("the data lack rpm, nozzle_angle"));
  ASSERT_EQ(
      RunUsvid("preprocess --data " + full + pre + (dir_ / "measured.csv").string()).exit_code, 0);
  const auto r = RunUsvid("preprocess --data " + commands + " --actuators " + actuators + pre +
                          (dir_ / "simulated.csv").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Dataset measured = ReadDatasetCsv((dir_ / "measured.csv").string()),
                simulated = ReadDatasetCsv((dir_ / "simulated.csv").string());
  for (const char* c : {"tau_x", "tau_y", "tau_n"}) {
    const Eigen::VectorXd& m = measured[c];
    const double error = (simulated[c] - m).norm(), size = (m.array() - m.mean()).matrix().norm();
    EXPECT_LT(error, 0.01 * size) << c;
  }
}

// Bad options: exit 2, one line naming the method, the option and what it allows, no model
// written. Each method's options come from its declaration (docs/options.md).
// Several records fitted jointly (issue 38): two msd runs from other seeds, each shorter than
// the one record above, give SINDy the true equation (docs/data.md#several-records-and-gaps):
// nothing is smoothed or simulated across the join. A record without a named channel, or an
// empty name in the list, is exit 2 naming it, and nothing is written.
TEST_F(IdentifyCliTest, SeveralRecordsAreFittedJointly) {
  const std::string a = (dir_ / "a.csv").string(), b = (dir_ / "b.csv").string();
  for (const auto& [file, seed] : {std::pair{a, 4}, std::pair{b, 5}})
    ASSERT_EQ(RunUsvid("simulate --vessel msd --maneuver random-steps --duration 150 --noise 0.01 "
                       "--seed " +
                       std::to_string(seed) + " --out " + file)
                  .exit_code,
              0);
  const auto out = (dir_ / "joint.json").string();
  const auto r =
      RunUsvid("identify --method sindy --vessel msd --data " + a + "," + b + " --out " + out);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("2 records, 300.0 s in all, fitted jointly"));
  EXPECT_THAT(r.err, HasSubstr("2 stretches between gaps or records"));
  const nlohmann::json m = ReadJsonFile(out);
  EXPECT_EQ(m.at("train").at("data"), a + "," + b);
  // The truth file's v' = (f - d v - k x) / m.
  const nlohmann::json truth = ReadJsonFile(dir_ / "a.truth.json").at("parameters");
  const double mass = truth.at("m"), k = truth.at("k");
  const nlohmann::json& p = m.at("parameters");
  ASSERT_TRUE(p.contains("v.x") && p.contains("v.f")) << p.dump();
  EXPECT_NEAR(p.at("v.f").get<double>(), 1.0 / mass, 0.05 / mass);
  EXPECT_NEAR(p.at("v.x").get<double>(), -k / mass, 0.05 * k / mass);

  WriteText(dir_ / "no_f.csv", "t,x,v\n0,0,0\n0.1,0,0\n");
  const auto missing = (dir_ / "missing.json").string();
  const auto bad = RunUsvid("identify --method sindy --vessel msd --states v --inputs f --data " +
                            a + "," + (dir_ / "no_f.csv").string() + " --out " + missing);
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_THAT(bad.err, HasSubstr("no_f.csv: no channel 'f' (every record of --data needs it)"));
  EXPECT_FALSE(fs::exists(missing));
  const auto empty =
      RunUsvid("identify --method sindy --vessel msd --data " + a + ", --out " + missing);
  EXPECT_EQ(empty.exit_code, 2);
  EXPECT_THAT(empty.err, HasSubstr("--data: an empty file name"));
  EXPECT_FALSE(fs::exists(missing));
}

// evaluate over several records scores each on its own, as evaluating it alone does (no free
// run crosses from one record into the next), lists them in order and gives per state the
// median fit % over the records; its figures are one per record.
TEST_F(IdentifyCliTest, EvaluateScoresEachOfSeveralRecordsOnItsOwn) {
  const std::string a = (dir_ / "a.csv").string(), b = (dir_ / "b.csv").string(),
                    c = (dir_ / "c.csv").string(), model = (dir_ / "m.json").string();
  for (const auto& [file, seed] : {std::pair{a, 4}, std::pair{b, 5}, std::pair{c, 6}})
    ASSERT_EQ(RunUsvid("simulate --vessel msd --maneuver random-steps --duration 100 --noise 0.01 "
                       "--seed " +
                       std::to_string(seed) + " --out " + file)
                  .exit_code,
              0);
  ASSERT_EQ(
      RunUsvid("identify --method sindy --vessel msd --data " + a + " --out " + model).exit_code,
      0);
  const auto alone = [&](const std::string& file) {
    const auto r = RunUsvid("evaluate --model " + model + " --data " + file);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return nlohmann::json::parse(r.out);
  };
  const auto out = (dir_ / "eval").string();
  const auto r = RunUsvid("evaluate --model " + model + " --data " + b + "," + c + " --out " + out);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json m = ReadJsonFile(out + "/metrics.json");
  ASSERT_EQ(m.at("records").size(), 2u);
  std::vector<double> v_fits;
  for (const auto& [i, file] : {std::pair{0, b}, std::pair{1, c}}) {
    const nlohmann::json& record = m.at("records").at(i);
    EXPECT_EQ(record.at("data"), file);
    EXPECT_EQ(record.at("channels"), alone(file).at("channels")) << file;
    v_fits.push_back(record.at("channels").at("v").at("fit_percent").get<double>());
  }
  EXPECT_EQ(m.at("summary").at("records"), 2);
  EXPECT_EQ(m.at("summary").at("diverged"), 0);
  EXPECT_DOUBLE_EQ(m.at("summary").at("median_fit_percent").at("v").get<double>(),
                   0.5 * (v_fits[0] + v_fits[1]));
  EXPECT_TRUE(fs::exists(out + "/free_run_1.svg") && fs::exists(out + "/free_run_2.svg"));
}

TEST_F(IdentifyCliTest, BadOptionsAreRefused) {
  const auto out = (dir_ / "bad.json").string();
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--method gp --vessel msd --operators +,^",
       "method gp: option 'operators' [\"+\",\"^\"] is not allowed: a list of +, -, *, /"},
      {"--method magic --vessel msd", "--method"},
      {"--method gp --states v,w --inputs f", "no channel 'w'"},
      {"--method gp --vessel msd --population 2",
       "method gp: option 'population' 2 is not allowed: a whole number in [4, 1000000]"},
      {"--method gp --vessel msd --population 2.5", "--population '2.5': method gp: allowed"},
      {"--method sindy --vessel msd --population 50",
       "--population: method sindy has no option 'population' (its options: --threshold"},
      {"--method gp --vessel msd --threshold 0.1", "method gp has no option 'threshold'"},
      {"--method sindy --vessel msd --library constant,cubic",
       "method sindy: option 'library' [\"constant\",\"cubic\"] is not allowed: a list of "
       "constant, products, abs"},
      {"--method sindy --vessel msd --threshold -1",
       "method sindy: option 'threshold' -1.0 is not allowed: a finite number >= 0"},
      {"--method fossen-ceres --vessel odin3dof --fit shooting",
       "method fossen-ceres: option 'fit' \"shooting\" is not allowed: one of simulation, "
       "equation"},
      {"--method hybrid --vessel msd --max-terms 9", "option 'max_terms' 9 is not allowed"},
      {"--method gp --vessel msd --derivative sg:20", "window must be odd"},
      {"--method eb-lr", "give --vessel, or --states and --inputs"},
      {"--method gp --vessel msd --preset fast", "option 'preset'"},
      {"--method gp --vessel msd --validation-fraction 0.9", "option 'validation_fraction'"},
      {"--method gp --vessel msd --validation-fraction -0.1", "option 'validation_fraction'"},
      {"--method gp --vessel msd --constant-iterations -1", "option 'constant_iterations'"},
      {"--method gp --vessel msd --horizon 0", "option 'horizon_s' 0.0 is not allowed: a finite "
                                               "number in (0, 600]"},
      {"--method gp --vessel msd --horizon-s 0", "option 'horizon_s'"},
      {"--method gp --vessel msd --ols-threshold 1", "a finite number in [0, 1)"},
      {"--method gp --states v --inputs tau_x --forces waterjet",
       "the data lack rpm, nozzle_angle, bucket_position"},
      {"--method gp --vessel msd --features froude", "the vessel has no hull length"},
      {"--method gp --vessel msd --features speed", "option 'features'"},
      {"--method sindy --vessel msd --features hinges", "the vessel has no hull length"},
      {"--method eb-lr --vessel msd --features froude",
       "--features: method eb-lr has no option 'features'"},
  };
  for (const auto& [args, message] : cases) {
    const auto r = RunUsvid("identify " + args + " --data " + data_ + " --out " + out);
    EXPECT_EQ(r.exit_code, 2) << args;
    EXPECT_THAT(r.err, HasSubstr(message)) << args;
    EXPECT_FALSE(fs::exists(out)) << args;
  }
}

}  // namespace
}  // namespace usvid
