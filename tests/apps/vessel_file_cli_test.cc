// `--vessel FILE` as a user runs it (docs/model.md#vessel-files): a ship given by its
// particulars simulates a zig-zag, the refit recovers a yaw damping hidden in a record of it
// through the same Jet-differentiated simulator as the compiled-in vessels, a particular is not
// a fit parameter, and a bad file stops the command with exit code 2, naming file:line and the
// key, and writing nothing.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "core/csv_dataset.h"
#include "core/json_file.h"
#include "tests/apps/run_usvid.h"

namespace usvid {
namespace {

using testing::FreshTempDir;
using ::testing::HasSubstr;
using testing::RunUsvid;
using testing::WriteText;
namespace fs = std::filesystem;

const std::string kEsso = std::string(USVID_SOURCE_DIR) + "/docs/vessels/files/esso-osaka.yaml";

TEST(VesselFileCliTest, AShipFromItsParticularsSimulatesAZigzag) {
  const fs::path dir = FreshTempDir();
  const std::string out = (dir / "zz.csv").string();
  const auto r = RunUsvid("simulate --vessel " + kEsso + " --maneuver zigzag:20/20 --out " + out);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("50 coefficients not given, estimated from the particulars"));
  const nlohmann::json truth = ReadJsonFile((dir / "zz.truth.json").string());
  // A 3 m tanker model at 10 rps: a zig-zag with overshoots of a few degrees.
  const double first = truth.at("maneuver").at("report").at("first_overshoot_deg");
  EXPECT_GT(first, 1.0);
  EXPECT_LT(first, 15.0);
  // `usvid vessel` lists each estimate with its source.
  const auto v =
      RunUsvid("vessel --vessel " + kEsso + " --points 2 --out " + (dir / "vessel").string());
  ASSERT_EQ(v.exit_code, 0) << v.err;
  EXPECT_THAT(v.out, HasSubstr("N_v = -0.1341 (Kijima et al. 1990)"));
  EXPECT_EQ(ReadJsonFile((dir / "vessel" / "vessel.json").string()).at("estimated").size(), 50u);
}

TEST(VesselFileCliTest, RefitRecoversAHiddenYawDampingAndKeepsParticularsFixed) {
  const fs::path dir = FreshTempDir();
  const std::string data = (dir / "random.csv").string();
  // The record's ship has 40 % more yaw damping N_r than the file's estimate (-0.0544).
  WriteText(dir / "truth.json", R"({"N_r": -0.0762})");
  ASSERT_EQ(RunUsvid("simulate --vessel " + kEsso +
                     " --maneuver random-steps --duration 400 "
                     "--seed 2 --params " +
                     (dir / "truth.json").string() + " --out " + data)
                .exit_code,
            0);
  const std::string model = (dir / "model.json").string();
  const auto r = RunUsvid("identify --method refit --vessel " + kEsso + " --data " + data +
                          " --refit-params N_r --out " + model);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json m = ReadJsonFile(model);
  EXPECT_NEAR(m.at("parameters").at("N_r").get<double>(), -0.0762, 0.002);
  EXPECT_EQ(m.at("vessel"), kEsso);

  const std::string refused = (dir / "refused.json").string();
  const auto l = RunUsvid("identify --method refit --vessel " + kEsso + " --data " + data +
                          " --refit-params L --out " + refused);
  EXPECT_EQ(l.exit_code, 2);
  EXPECT_THAT(l.err, HasSubstr("'L' is a particular"));
  EXPECT_FALSE(fs::exists(refused));
}

TEST(VesselFileCliTest, ASuiteRunsOnAVesselFile) {
  const fs::path dir = FreshTempDir();
  WriteText(dir / "suite.json", R"({"name": "file", "vessels": [")" + kEsso + R"("],
      "train_maneuvers": ["zigzag:20/20"], "test_maneuvers": ["turning:35"],
      "methods": ["nominal"], "seeds": [1]})");
  const auto r = RunUsvid("compare --suite " + (dir / "suite.json").string() + " --out " +
                          (dir / "out").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // The figures are named by the file's stem, not its path.
  EXPECT_TRUE(fs::exists(dir / "out" / "fit_esso-osaka.svg"));
  EXPECT_TRUE(fs::exists(dir / "out" / "report.html"));
}

// The Esso Osaka file with `model: none` under wind: the same ship, whose model ignores the wind.
fs::path EssoWithoutWind(const fs::path& dir) {
  std::ifstream in(kEsso);
  std::stringstream text;
  text << in.rdbuf();
  WriteText(dir / "esso-no-wind.yaml", text.str() + "  model: none\n");
  return dir / "esso-no-wind.yaml";
}

// An equation method given the logged wind's body components (wind_u, wind_v, derived from the
// record's wind_speed and wind_direction: docs/data.md#derived-channels) models what the wind
// does; without them its equations explain the wind's push by the rudder and propeller, and
// their free run on another gusty record diverges. Both records: Esso Osaka under a 3 m/s wind
// from 60 deg, with gusts drawn from their seeds.
TEST(VesselFileCliTest, EquationMethodsReadTheLoggedWindThroughItsBodyComponents) {
  const fs::path dir = FreshTempDir();
  for (const char* seed : {"3", "4"}) {
    const auto s = RunUsvid("simulate --vessel " + kEsso +
                            " --maneuver random-steps --duration 600 --wind 3:60 --noise 0.005 "
                            "--seed " +
                            std::string(seed) + " --out " + (dir / ("w" + std::string(seed) + ".csv")).string());
    ASSERT_EQ(s.exit_code, 0) << s.err;
  }
  std::map<std::string, nlohmann::json> fits;
  for (const std::string inputs : {"n,delta", "n,delta,wind_speed,wind_u,wind_v"}) {
    const fs::path out = dir / (inputs.size() > 8 ? "wind" : "calm");
    const auto i = RunUsvid("identify --method sindy --states u,v,r --inputs " + inputs +
                            " --library constant,products,abs,inputs --data " +
                            (dir / "w3.csv").string() + " --out " + (out.string() + ".json"));
    ASSERT_EQ(i.exit_code, 0) << i.err;
    const auto e = RunUsvid("evaluate --model " + out.string() + ".json --data " +
                            (dir / "w4.csv").string() + " --out " + out.string());
    ASSERT_EQ(e.exit_code, 0) << e.err;
    fits[inputs] = ReadJsonFile((out / "metrics.json").string());
  }
  const nlohmann::json& calm = fits.at("n,delta");
  const nlohmann::json& wind = fits.at("n,delta,wind_speed,wind_u,wind_v");
  EXPECT_TRUE(calm.at("diverged").get<bool>());  // -859 % r fit when this test was written
  EXPECT_FALSE(wind.at("diverged").get<bool>());
  EXPECT_GT(wind.at("channels").at("r").at("fit_percent").get<double>(), 20.0);  // 40.3 %
  // A record without the wind's direction cannot give its components: exit 2, naming the channel.
  Dataset no_direction = ReadDatasetCsv((dir / "w3.csv").string());
  no_direction.Remove("wind_direction");
  WriteDatasetCsv((dir / "no_direction.csv").string(), no_direction);
  const auto bad = RunUsvid("identify --method sindy --states u,v,r --inputs n,delta,wind_u --data " +
                            (dir / "no_direction.csv").string() + " --out " +
                            (dir / "bad.json").string());
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_THAT(bad.err, ::testing::HasSubstr("no channel 'wind_u', nor wind_speed and "
                                            "wind_direction to derive it from"));
  EXPECT_FALSE(fs::exists(dir / "bad.json"));
}

TEST(VesselFileCliTest, DiagnoseFindsTheWindAModelIgnoresAndItsSize) {
  // The truth: random steps under a gusty true wind of 3 m/s from 60 deg, which the record logs
  // as the relative wind aboard; the ship feels all of it (effect wind, scale 1, on a model
  // without wind).
  const fs::path dir = FreshTempDir();
  const std::string no_wind = EssoWithoutWind(dir).string();
  const std::string data = (dir / "windy.csv").string();
  const auto s = RunUsvid("simulate --vessel " + no_wind +
                          " --maneuver random-steps --duration 400 --wind 3:60 --effect wind=1 "
                          "--noise 0.01 --seed 3 --out " +
                          data);
  ASSERT_EQ(s.exit_code, 0) << s.err;
  const nlohmann::json truth = ReadJsonFile((dir / "windy.truth.json").string());
  EXPECT_EQ(truth.at("effects").at(0).at("effect"), "wind");
  EXPECT_NEAR(truth.at("maneuver").at("report").at("true_wind").at("from_deg").get<double>(), 60.0,
              1e-9);
  // Against the model that ignores the wind, diagnose names it and sizes it.
  const auto d = RunUsvid("diagnose --vessel " + no_wind + " --data " + data + " --out " +
                          (dir / "without").string());
  ASSERT_EQ(d.exit_code, 0) << d.err;
  const nlohmann::json without = ReadJsonFile((dir / "without" / "diagnosis.json").string());
  EXPECT_EQ(without.at("cause"), "wind");
  const nlohmann::json& best = without.at("candidates").at(0);
  EXPECT_NEAR(best.at("parameters").at("scale").get<double>(), 1.0, 0.05);
  EXPECT_GT(without.at("gain").at("heldout_error_reduction").get<double>(), 0.5);
  // Against the model with the wind (the same ship with model fujiwara), nothing is missing.
  const auto w = RunUsvid("diagnose --vessel " + kEsso + " --data " + data + " --out " +
                          (dir / "with").string());
  ASSERT_EQ(w.exit_code, 0) << w.err;
  EXPECT_EQ(ReadJsonFile((dir / "with" / "diagnosis.json").string()).at("cause"), "none");
  // A vessel without a wind model cannot hide one.
  const auto bad = RunUsvid("simulate --vessel odin3dof --maneuver zigzag --effect wind=1 --out " +
                            (dir / "bad.csv").string());
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_THAT(bad.err, HasSubstr("odin3dof has no wind model"));
  EXPECT_FALSE(fs::exists(dir / "bad.csv"));
}

// A closed-loop replay follows the record's logged wind as it goes: the model that made a
// zig-zag under a beam wind of 3 m/s replays it to 0.13 deg of its first overshoot; the same
// record without its wind columns replays calm, 2.3 deg off.
TEST(VesselFileCliTest, AClosedLoopReplayFollowsTheLoggedWind) {
  const fs::path dir = FreshTempDir();
  const std::string windy = (dir / "windy.csv").string(), model = (dir / "nominal.json").string();
  ASSERT_EQ(RunUsvid("simulate --vessel " + kEsso +
                     " --maneuver zigzag:20/20 --wind 3:90 --seed 2 --out " + windy)
                .exit_code,
            0);
  ASSERT_EQ(RunUsvid("identify --method nominal --vessel " + kEsso + " --data " + windy +
                     " --out " + model)
                .exit_code,
            0);
  // The record without its wind: every column but wind_speed and wind_direction.
  std::ifstream in(windy);
  std::ofstream calm(dir / "calm.csv");
  for (std::string line; std::getline(in, line);) {
    for (int drop = 0; drop < 2; ++drop) line = line.substr(0, line.rfind(','));
    calm << line << "\n";
  }
  calm.close();
  auto first_overshoot_error = [&](const std::string& data, const std::string& name) {
    const auto r = RunUsvid("evaluate --model " + model + " --data " + data +
                            " --maneuver zigzag:20/20 --out " + (dir / name).string());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return std::abs(ReadJsonFile((dir / name / "metrics.json").string())
                        .at("closed_loop")
                        .at("first_overshoot_error_deg")
                        .get<double>());
  };
  EXPECT_LT(first_overshoot_error(windy, "windy"), 0.5);
  EXPECT_GT(first_overshoot_error((dir / "calm.csv").string(), "calm"), 1.0);
}

// `--maneuver zigzag` without its angle replays the zig-zag the record holds: a port-first
// 15/15 zig-zag of the file's ship is replayed as zigzag:-15/15, to its own first overshoot
// (metrics/maneuver_of_record.h).
TEST(VesselFileCliTest, AManeuverWithoutItsAngleIsReadFromTheRecord) {
  const fs::path dir = FreshTempDir();
  const std::string zz = (dir / "zz.csv").string(), model = (dir / "nominal.json").string();
  ASSERT_EQ(
      RunUsvid("simulate --vessel " + kEsso + " --maneuver zigzag:-15/15 --out " + zz).exit_code,
      0);
  ASSERT_EQ(
      RunUsvid("identify --method nominal --vessel " + kEsso + " --data " + zz + " --out " + model)
          .exit_code,
      0);
  const auto r = RunUsvid("evaluate --model " + model + " --data " + zz +
                          " --maneuver zigzag --out " + (dir / "eval").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json loop =
      ReadJsonFile((dir / "eval" / "metrics.json").string()).at("closed_loop");
  EXPECT_EQ(loop.at("maneuver"), "zigzag:-15/15");
  ASSERT_EQ(loop.at("status"), "ok");
  EXPECT_LT(std::abs(loop.at("first_overshoot_error_deg").get<double>()), 0.05);
}

// A measured suite's test entry with "maneuver": "zigzag" replays the same way.
TEST(VesselFileCliTest, AMeasuredSuitesBareZigzagIsReadFromItsRecord) {
  const fs::path dir = FreshTempDir();
  const std::string zz = (dir / "zz.csv").string();
  ASSERT_EQ(
      RunUsvid("simulate --vessel " + kEsso + " --maneuver zigzag:-15/15 --out " + zz).exit_code,
      0);
  WriteText(dir / "suite.json", R"({"name": "bare", "vessels": [")" + kEsso + R"("],
      "data": {"train": [{"name": "zz", "file": "zz.csv"}],
               "test": [{"name": "zz again", "file": "zz.csv", "maneuver": "zigzag"}]},
      "methods": ["nominal"]})");
  const auto r = RunUsvid("compare --suite " + (dir / "suite.json").string() + " --out " +
                          (dir / "out").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json row = ReadJsonFile((dir / "out" / "results.json").string()).at("rows").at(0);
  EXPECT_EQ(row.at("closed_loop").at("maneuver"), "zigzag:-15/15");
  EXPECT_EQ(row.at("closed_loop").at("status"), "ok");
}

// The relative wind a log holds is the true wind seen from the hull that logged it. A model that
// turns otherwise meets that true wind on its own heading: a free run and a closed-loop replay
// of another ship's record give the model what the same true wind does to it, not the logged
// hull's wind. Both ships: Esso Osaka turning at 35 deg under a gusty beam wind of 1.5 m/s from
// 90 deg (seed 2); the model's yaw damping N_r is -0.1 against the file's -0.054, so its heading
// parts from the logged hull's by up to 1.4 rad.
TEST(VesselFileCliTest, AModelMeetsTheLoggedTrueWindOnItsOwnHeading) {
  const fs::path dir = FreshTempDir();
  const std::string params = (dir / "params.json").string();
  WriteText(params, R"({"N_r": -0.1})");
  auto simulate = [&](const std::string& name, const std::string& extra) {
    const auto r =
        RunUsvid("simulate --vessel " + kEsso + extra + " --out " + (dir / name).string());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return ReadDatasetCsv((dir / name).string());
  };
  const std::string turn = " --maneuver turning:35 --duration 300 --wind 1.5:90 --seed 2";
  const Dataset logged = simulate("logged.csv", turn);
  const Dataset model = simulate("model.csv", turn + " --params " + params);
  auto largest_gap = [](const Dataset& a, const Dataset& b, const std::string& c) {
    return (a[c] - b[c]).cwiseAbs().maxCoeff();
  };
  ASSERT_GT(largest_gap(logged, model, "psi"), 0.5);
  // The free run of the model on the logged inputs, from the model's own first state.
  Dataset inputs = logged;
  for (const char* c : {"u", "v", "r"}) {
    Eigen::VectorXd v = inputs[c];
    v(0) = model[c](0);
    inputs.Set(c, v);
  }
  WriteDatasetCsv((dir / "inputs.csv").string(), inputs);
  const Dataset free =
      simulate("free.csv", " --params " + params + " --inputs " + (dir / "inputs.csv").string());
  EXPECT_LT(largest_gap(free, model, "psi"), 0.005);  // 1e-4 rad when this test was written
  EXPECT_LT(largest_gap(free, model, "u"), 0.001);
  // Without the logged heading the true wind is unknown, and the relative wind is taken as
  // logged: the free run then feels the logged hull's wind.
  inputs.Remove("psi");
  WriteDatasetCsv((dir / "no_heading.csv").string(), inputs);
  const Dataset as_logged = simulate(
      "as_logged.csv", " --params " + params + " --inputs " + (dir / "no_heading.csv").string());
  EXPECT_GT(largest_gap(as_logged, model, "psi"), 0.05);
  // The closed-loop replay of the model's turn on either ship's record: the same true wind, so
  // the same tactical diameter (9.15 and 9.12 m; 9.44 m on the logged hull's record with its
  // relative wind as logged), though the two ships' measured diameters differ by 2.6 m.
  const std::string fitted = (dir / "model.json").string();
  ASSERT_EQ(RunUsvid("identify --method nominal --vessel " + kEsso + " --params " + params +
                     " --data " + (dir / "model.csv").string() + " --out " + fitted)
                .exit_code,
            0);
  auto replayed = [&](const std::string& data) {
    const auto r = RunUsvid("evaluate --model " + fitted + " --data " + (dir / data).string() +
                            " --maneuver turning:35 --out " + (dir / (data + ".eval")).string());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return ReadJsonFile((dir / (data + ".eval") / "metrics.json").string()).at("closed_loop");
  };
  const nlohmann::json on_logged = replayed("logged.csv"), on_own = replayed("model.csv");
  EXPECT_GT(std::abs(on_logged.at("measured").at("tactical_diameter_m").get<double>() -
                     on_own.at("measured").at("tactical_diameter_m").get<double>()),
            2.0);
  EXPECT_NEAR(on_logged.at("model").at("tactical_diameter_m").get<double>(),
              on_own.at("model").at("tactical_diameter_m").get<double>(), 0.1);
}

// fossen-ceres on a vessel file's ship: the Fossen 3-DOF form with the rudder-propeller map in
// revolutions per second, started from KVLCC2's values scaled to the 3 m model by Froude's law.
// Trained on random steps (the propeller reversing), it free-runs a held-out zig-zag of the
// same ship.
TEST(VesselFileCliTest, FossenCeresFitsAVesselFilesShip) {
  const fs::path dir = FreshTempDir();
  const std::string train = (dir / "train.csv").string(), test = (dir / "test.csv").string();
  ASSERT_EQ(
      RunUsvid("simulate --vessel " + kEsso +
               " --maneuver random-steps --duration 600 --noise 0.005 --seed 4 --out " + train)
          .exit_code,
      0);
  ASSERT_EQ(
      RunUsvid("simulate --vessel " + kEsso + " --maneuver zigzag:20/20 --seed 5 --out " + test)
          .exit_code,
      0);
  const std::string model = (dir / "fossen.json").string();
  const auto r = RunUsvid("identify --method fossen-ceres --vessel " + kEsso + " --data " + train +
                          " --out " + model);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json m = ReadJsonFile(model);
  EXPECT_EQ(m.at("fossen").at("model"), "fossen-rudder-rps");
  // The file's rudder sign is MMG's: a positive angle turns to starboard, so the rudder's moment
  // gain is positive.
  EXPECT_GT(m.at("parameters").at("Tn").get<double>(), 0.0);
  const auto e = RunUsvid("evaluate --model " + model + " --data " + test);
  ASSERT_EQ(e.exit_code, 0) << e.err;
  const nlohmann::json score = nlohmann::json::parse(e.out);
  EXPECT_GT(score.at("channels").at("r").at("fit_percent").get<double>(),
            60.0);  // 76.3 % when written
}

TEST(VesselFileCliTest, ABadFileIsExitTwoNamingTheLineAndWritesNothing) {
  const fs::path dir = FreshTempDir();
  const fs::path ship = dir / "ship.yaml";
  WriteText(ship,
            "hull:\n  L: 3.0\n  B: 0.49\n  d: 0.2\n  C_b: 0.83\n  mass: 245\n  x_G: 0.09\n"
            "  k_zz: 0.25\n  draught: 0.2\npropeller:\n  D: 0.084\nrudder:\n  area: 0.0106\n"
            "  span: 0.13\ncontrols:\n  rudder_sign: mmg\n  rudder_max_deg: 35\n  n_max: 20\n"
            "  n_cruise: 10\n");
  const std::string out = (dir / "zz.csv").string();
  const auto r = RunUsvid("simulate --vessel " + ship.string() + " --maneuver zigzag --out " + out);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("ship.yaml:9:3: hull.draught: unknown key"));
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace usvid
