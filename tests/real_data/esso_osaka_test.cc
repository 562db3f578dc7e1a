// The Esso Osaka free-running model tests (../shared/data/esso-osaka: a 3 m tanker model in an
// outdoor pond, GPS-derived u and v) through the binary, as docs/real-data.md reports them: the
// data-driven methods trained on eight runs at once and free-run on eight others
// (docs/studies/esso-osaka.json). Issue 38: every equation of every method keeps terms (SINDy
// through its weak form: from the derivatives it keeps none), every method's free runs hold on
// every held-out run, and SINDy's, which do not depend on the seed, fit r to issue 38's bars: 70 %
// on every held-out zig-zag and 50 % on a random run. Issue 39: the model built from
// the vessel's main particulars alone (docs/vessels/files/esso-osaka.yaml) replays each shared
// zig-zag closed-loop from its execute, after the operator's hand steering from rest, within
// 5 deg of its first overshoot; the study's refit meets the refit bars on the shared
// runs it holds out.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "core/json_file.h"
#include "tests/apps/run_usvid.h"

namespace usvid {
namespace {

namespace fs = std::filesystem;
using testing::FreshTempDir;
using testing::RunUsvid;

const std::string kData = std::string(USVID_SHARED_DATA_DIR) + "/esso-osaka";

TEST(EssoOsakaTest, EveryMethodKeepsTermsAndHoldsOnTheHeldOutRuns) {
  if (!fs::exists(kData)) GTEST_SKIP() << "shared data absent: " << kData;
  const fs::path dir = FreshTempDir();
  const auto r = RunUsvid("compare --suite " + std::string(USVID_SOURCE_DIR) +
                          "/docs/studies/esso-osaka.json --out " + (dir / "study").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json results = ReadJsonFile((dir / "study" / "results.json").string());
  std::vector<double> sindy_zigzag_r, sindy_turning_r, sindy_random_r;
  int sindy_rows = 0;
  for (const auto& row : results.at("rows")) {
    // A method whose equation kept no term fails its cell (methods/sindy/sindy_method.cc).
    ASSERT_EQ(row.at("status"), "ok") << row.dump();
    // No free run leaves the bounds. GP's seed 2 did on the random run of 31 Jul 12:48, which
    // goes further astern than any training run, until its yaw damping u*r was written with |u|
    // (methods/gp/astern_symmetry.h).
    EXPECT_FALSE(row.value("diverged", false))
        << row.at("method") << " seed " << row.at("seed") << " on " << row.at("test_maneuver");
    if (row.at("method") != "sindy") continue;
    ++sindy_rows;
    const std::string test = row.at("test_maneuver").get<std::string>();
    const double r_fit = row.at("channel_fit_percent").at("r").get<double>();
    if (test.starts_with("zigzag")) sindy_zigzag_r.push_back(r_fit);
    if (test.starts_with("turning")) sindy_turning_r.push_back(r_fit);
    if (test.starts_with("random")) sindy_random_r.push_back(r_fit);
  }
  EXPECT_EQ(sindy_rows, 8);
  ASSERT_EQ(sindy_zigzag_r.size(), 4u);
  ASSERT_EQ(sindy_turning_r.size(), 2u);
  ASSERT_EQ(sindy_random_r.size(), 2u);
  // With the rudder's inflow in its library (the rudder's force growing with |u| u, u n+ and
  // n+ n+; docs/baselines.md#the-rudders-inflow) SINDy fits r on every held-out zig-zag to
  // issue 38's 70 %: 84.2, 80.0, 85.8 and 84.4 % when docs/real-data.md was written, against
  // 74.1, 54.4, 73.3 and 80.6 % with u delta alone. The 15/15 zig-zag of 13:22, at the lowest
  // propeller speed (10 1/s against 12-17), is the one a rudder force in u delta overturned.
  EXPECT_GT(*std::ranges::min_element(sindy_zigzag_r), 70.0);
  // And one of the two random runs (6 Aug) to issue 38's 50 %: 61.6 %, against 49.2 %.
  EXPECT_GT(*std::ranges::max_element(sindy_random_r), 50.0);
  // The turning circles: 84.3 and 73.3 %, against 47.3 % on both without the wind.
  for (const double r_fit : sindy_turning_r) EXPECT_GT(r_fit, 60.0);
}

// The shared zig-zags and their test angles (A = B), with the time of the execute the rudder and
// heading show: the first full-angle order held until the heading has turned by B.
struct Zigzag {
  const char* file;
  int angle;  // the first order's, starboard positive: 13:50 and 14:03 turn to port first
  double execute_s;
};

TEST(EssoOsakaTest, TheParticularsAloneReplayEachZigzagFromItsExecute) {
  if (!fs::exists(kData)) GTEST_SKIP() << "shared data absent: " << kData;
  const fs::path dir = FreshTempDir();
  const std::string vessel =
      std::string(USVID_SOURCE_DIR) + "/docs/vessels/files/esso-osaka.yaml";
  const std::string map =
      "\"t=t [s],north=x_position_mid [m],east=y_position_mid [m],psi=psi_hat [rad],"
      "u=u_velo [m/s],v=vm_velo [m/s],r=r_angvelo [rad/s],n=n_prop [rps],"
      "delta=delta_rudder [rad],wind_speed=wind_velo_relative_mid [m/s],"
      "wind_direction=wind_dir_relative_mid [rad]\"";
  const std::string model = (dir / "nominal.json").string();
  bool first = true;
  for (const Zigzag& z :
       {Zigzag{"13_04_24", 20, 44.2}, Zigzag{"13_14_21", 30, 18.4}, Zigzag{"13_22_52", 15, 36.1},
        Zigzag{"13_29_19", 15, 42.6}, Zigzag{"13_50_28", -30, 42.3}, Zigzag{"13_57_45", 20, 26.5},
        Zigzag{"14_03_39", -20, 35.2}}) {
    const std::string csv = (dir / (std::string(z.file) + ".csv")).string();
    ASSERT_EQ(RunUsvid("import --format csv --data " + kData + "/zigzag/zigzag_31-Jul-2020_" +
                       z.file + ".csv --map " + map + " --out " + csv)
                  .exit_code,
              0);
    if (first) {  // no fitting: the model is the vessel file
      ASSERT_EQ(RunUsvid("identify --method nominal --vessel " + vessel + " --data " + csv +
                         " --out " + model)
                    .exit_code,
                0);
      first = false;
    }
    const std::string spec =
        "zigzag:" + std::to_string(z.angle) + "/" + std::to_string(std::abs(z.angle));
    const fs::path out = dir / z.file;
    const auto r = RunUsvid("evaluate --model " + model + " --data " + csv + " --maneuver " +
                            spec + " --out " + out.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const nlohmann::json loop = ReadJsonFile((out / "metrics.json").string()).at("closed_loop");
    ASSERT_EQ(loop.at("status"), "ok") << z.file;
    // Replayed from the lead-in, 5 s before the execute.
    EXPECT_NEAR(loop.at("replayed_from_s").get<double>(), z.execute_s - 5.0, 1.0) << z.file;
    EXPECT_LT(std::abs(loop.at("first_overshoot_error_deg").get<double>()), 5.0) << z.file;
  }
}

// The zig-zag of 31 Jul 13:04 goes on recording for 13 s after its propeller stopped, while
// the unlogged thrusters bring the model back: its yaw rate there, with the rudder amidships,
// swings wider than anywhere in the zig-zag. `--end-at-stop n` ends the record at the stop
// (docs/data.md#the-end-of-a-test).
TEST(EssoOsakaTest, TheRecoveryAfterAZigzagIsDropped) {
  if (!fs::exists(kData)) GTEST_SKIP() << "shared data absent: " << kData;
  const fs::path dir = FreshTempDir();
  const std::string map = "\"t=t [s],r=r_angvelo [rad/s],n=n_prop [rps],delta=delta_rudder [rad]\"";
  const std::string log = kData + "/zigzag/zigzag_31-Jul-2020_13_04_24.csv";
  const std::string whole = (dir / "whole.csv").string(), test = (dir / "test.csv").string();
  ASSERT_EQ(
      RunUsvid("import --format csv --data " + log + " --map " + map + " --out " + whole).exit_code,
      0);
  const auto r = RunUsvid("import --format csv --data " + log + " --map " + map +
                          " --end-at-stop n --out " + test);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.err, ::testing::HasSubstr("ended where n stopped, at t = 127.1 s: 13.1 s"));
  auto largest_rate = [](const std::string& file, double from_s) {
    std::ifstream in(file);
    std::string line;
    std::getline(in, line);  // t,r,n,delta
    double largest = 0.0;
    while (std::getline(in, line)) {
      std::stringstream s(line);
      std::string t, rate;
      std::getline(s, t, ',');
      std::getline(s, rate, ',');
      if (std::stod(t) >= from_s) largest = std::max(largest, std::abs(std::stod(rate)));
    }
    return largest;
  };
  const double in_test = largest_rate(test, 0.0), after = largest_rate(whole, 127.2);
  EXPECT_GT(after, in_test) << "the recovery's yaw rate against the zig-zag's";
}

// Issue 39's bars for the refit, on the shared runs the study holds out: the refit of the
// study (docs/studies/esso-osaka-mmg.json: thirteen coefficients, each record weighed alike,
// fitted jointly on its eight training runs) replays each held-out zig-zag closed-loop within
// 2 deg of its first overshoot and each held-out turning circle within 10 % of its tactical
// diameter, and free-runs each zig-zag with an r fit of at least 75 %. Measured when written
// (docs/real-data.md#refit-n-vrr): 0.56, 0.31, 1.43, 0.99 deg; +9.0 and +5.4 %; 77.0, 77.5,
// 86.6, 78.9 %. The circle of 14 Sep 13:39 makes it by a point (with the twelve coefficients
// before N_vrr, 10.3 %; with 36 s segments, 12.6 %): a change that moves it past 10 % moves the
// refit's turns, and is worth a look at the study's table. The papers' own test runs, which are
// not shared, are the real test.
TEST(EssoOsakaTest, TheStudysRefitReplaysTheHeldOutZigzagsAndCircles) {
  if (!fs::exists(kData)) GTEST_SKIP() << "shared data absent: " << kData;
  const fs::path dir = FreshTempDir();
  const fs::path studies = fs::path(USVID_SOURCE_DIR) / "docs" / "studies";
  nlohmann::json suite =
      ReadJsonFile((studies / "esso-osaka-mmg.json").string(), JsonComments::kAllowed);
  // The refit alone, and the study's files made absolute: the suite is written elsewhere.
  nlohmann::json refit;
  for (const auto& m : suite.at("methods"))
    if (m.is_object() && m.at("method") == "refit") refit = m;
  ASSERT_FALSE(refit.is_null()) << "the study has no refit";
  suite["methods"] = nlohmann::json::array({refit});
  const auto absolute = [&](nlohmann::json& file) {
    file = fs::weakly_canonical(studies / file.get<std::string>()).string();
  };
  for (auto& v : suite.at("vessels")) absolute(v);
  for (auto& f : suite.at("data").at("train").at(0).at("file")) absolute(f);
  for (auto& t : suite.at("data").at("test")) absolute(t.at("file"));
  const fs::path suite_file = dir / "refit.json";
  std::ofstream(suite_file) << suite.dump(1);
  const auto r =
      RunUsvid("compare --suite " + suite_file.string() + " --out " + (dir / "study").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json results = ReadJsonFile((dir / "study" / "results.json").string());
  int zigzags = 0, circles = 0;
  for (const auto& row : results.at("rows")) {
    ASSERT_EQ(row.at("status"), "ok") << row.dump();
    const std::string test = row.at("test_maneuver").get<std::string>();
    if (!test.starts_with("zigzag") && !test.starts_with("turning")) continue;
    const nlohmann::json& loop = row.at("closed_loop");
    ASSERT_EQ(loop.at("status"), "ok") << test;
    if (test.starts_with("zigzag")) {
      ++zigzags;
      EXPECT_LT(std::abs(loop.at("first_overshoot_error_deg").get<double>()), 2.0) << test;
      EXPECT_GE(row.at("channel_fit_percent").at("r").get<double>(), 75.0) << test;
    } else {
      ++circles;
      const double measured = loop.at("measured").at("tactical_diameter_m").get<double>();
      const double model = loop.at("model").at("tactical_diameter_m").get<double>();
      EXPECT_LT(std::abs(model / measured - 1.0), 0.10) << test;
    }
  }
  EXPECT_EQ(zigzags, 4);
  EXPECT_EQ(circles, 2);
}

// Esso Osaka's logs hold the rudder's orders, which jump in one sample
// (metrics/recorded_yaw_rate.h). A data-driven model learned the hull's answer to those orders, the
// steering gear's lag inside it, so its closed-loop replay steps the order as the log did; slewed
// again at the vessel's 20 deg/s, SINDy met the lag twice and overshot every one of the study's
// four held-out zig-zags (by 0.55-4.09 deg, mean 2.80, against the particulars' 2.14). The
// particulars' model simulates its own gear and keeps the vessel's rate. SINDy as the real suite's
// track runs it, trained on the study's eight runs: its mean first-overshoot error over the four
// below the particulars' (0.51 against 2.14 deg when this test was written).
TEST(EssoOsakaTest, ADataDrivenReplayStepsTheRudderAsTheLogDid) {
  if (!fs::exists(kData)) GTEST_SKIP() << "shared data absent: " << kData;
  const fs::path dir = FreshTempDir();
  const fs::path studies = fs::path(USVID_SOURCE_DIR) / "docs" / "studies";
  nlohmann::json suite =
      ReadJsonFile((studies / "esso-osaka-mmg.json").string(), JsonComments::kAllowed);
  suite["methods"] =
      nlohmann::json::array({"nominal",
                             {{"method", "sindy"},
                              {"states", {"u", "v", "r"}},
                              {"inputs", {"n", "delta", "wind_speed", "wind_u", "wind_v"}},
                              {"library", {"constant", "products", "abs", "inputs", "rudder"}},
                              {"weak_window_s", 20}}});
  const auto absolute = [&](nlohmann::json& file) {
    file = fs::weakly_canonical(studies / file.get<std::string>()).string();
  };
  for (auto& v : suite.at("vessels")) absolute(v);
  for (auto& f : suite.at("data").at("train").at(0).at("file")) absolute(f);
  for (auto& t : suite.at("data").at("test")) absolute(t.at("file"));
  const fs::path suite_file = dir / "sindy.json";
  std::ofstream(suite_file) << suite.dump(1);
  const auto r =
      RunUsvid("compare --suite " + suite_file.string() + " --out " + (dir / "study").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json results = ReadJsonFile((dir / "study" / "results.json").string());
  std::map<std::string, std::vector<double>> errors;  // per method, |first overshoot error|
  for (const auto& row : results.at("rows")) {
    ASSERT_EQ(row.at("status"), "ok") << row.dump();
    if (!row.at("test_maneuver").get<std::string>().starts_with("zigzag")) continue;
    const nlohmann::json& loop = row.at("closed_loop");
    ASSERT_EQ(loop.at("status"), "ok") << row.dump();
    errors[row.at("method").get<std::string>()].push_back(
        std::abs(loop.at("first_overshoot_error_deg").get<double>()));
  }
  ASSERT_EQ(errors["sindy"].size(), 4u);
  ASSERT_EQ(errors["nominal"].size(), 4u);
  auto mean = [](const std::vector<double>& v) {
    double sum = 0.0;
    for (const double x : v) sum += x;
    return sum / static_cast<double>(v.size());
  };
  EXPECT_LT(mean(errors["sindy"]), mean(errors["nominal"]));
  // `usvid info --zigzag` says so of a log: its rudder jumps by 40 deg between two samples.
  const std::string log = (dir / "zz.csv").string();
  ASSERT_EQ(RunUsvid("import --format csv --data " + kData +
                     "/zigzag/zigzag_31-Jul-2020_13_04_24.csv --map \"t=t [s],psi=psi_hat [rad],"
                     "r=r_angvelo [rad/s],n=n_prop [rps],delta=delta_rudder [rad]\" --out " +
                     log)
                .exit_code,
            0);
  const auto info = RunUsvid("info --data " + log + " --zigzag");
  ASSERT_EQ(info.exit_code, 0) << info.err;
  EXPECT_THAT(info.out, ::testing::HasSubstr("rudder delta: its large moves at 397 deg/s (steps "
                                             "between two samples: the log holds the rudder's "
                                             "orders"));
}

TEST(EssoOsakaTest, DiagnoseNamesTheLoggedWindThatAModelIgnores) {
  // The random run of 31 Jul 12:29 (684 s, relative wind 0.3-3 m/s). Against the model from the
  // particulars without its wind (model: none), diagnose names the wind; diagnosed again with
  // the wind it fitted (its model.json), nothing. Fujiwara's wind from the areas alone explains
  // most of it too. Measured when written (docs/real-data.md#wind): scale 0.64, held-out error
  // 0.229 -> 0.090; then cause none; the file's own wind: nominal error 0.102.
  if (!fs::exists(kData)) GTEST_SKIP() << "shared data absent: " << kData;
  const fs::path dir = FreshTempDir();
  const std::string csv = (dir / "random.csv").string();
  ASSERT_EQ(RunUsvid("import --format csv --data " + kData +
                     "/random/random_31-Jul-2020_12_29_58.csv --map \"t=t [s],"
                     "north=x_position_mid [m],east=y_position_mid [m],psi=psi_hat [rad],"
                     "u=u_velo [m/s],v=vm_velo [m/s],r=r_angvelo [rad/s],n=n_prop [rps],"
                     "delta=delta_rudder [rad],wind_speed=wind_velo_relative_mid [m/s],"
                     "wind_direction=wind_dir_relative_mid [rad]\" --out " +
                     csv)
                .exit_code,
            0);
  const std::string with_wind =
      std::string(USVID_SOURCE_DIR) + "/docs/vessels/files/esso-osaka.yaml";
  std::ifstream in(with_wind);
  std::stringstream text;
  text << in.rdbuf();
  const fs::path without_wind = dir / "esso-no-wind.yaml";
  std::ofstream(without_wind) << text.str() << "  model: none\n";
  auto diagnose = [&](const std::string& vessel, const std::string& extra,
                      const std::string& name) {
    const auto r = RunUsvid("diagnose --vessel " + vessel + extra + " --data " + csv + " --out " +
                            (dir / name).string());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return ReadJsonFile((dir / name / "diagnosis.json").string());
  };
  const nlohmann::json without = diagnose(without_wind.string(), "", "without");
  EXPECT_EQ(without.at("cause"), "wind");
  EXPECT_GT(without.at("gain").at("heldout_error_reduction").get<double>(), 0.2);
  const nlohmann::json again = diagnose(
      without_wind.string(), " --params " + (dir / "without" / "model.json").string(), "again");
  for (const auto& cause : again.at("causes")) EXPECT_NE(cause, "wind");
  const nlohmann::json with = diagnose(with_wind, "", "with");
  EXPECT_LT(with.at("nominal").at("heldout_error").get<double>(),
            0.6 * without.at("nominal").at("heldout_error").get<double>());
}

}  // namespace
}  // namespace usvid
