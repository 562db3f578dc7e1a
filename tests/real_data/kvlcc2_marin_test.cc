// The KVLCC2 free-running model tests (MARIN, SIMMAN 2008; ../shared/data/kvlcc2-marin) through
// the binary, as docs/real-data.md reports them: the measured zig-zag overshoots, the nominal
// MMG model's first overshoot and why it is low (the diagnosis: the surge resistance), and every
// method trained on zig-zag 20/-20 and scored in free run on zig-zag -20/20 and the 35 deg
// turning circle (docs/studies/kvlcc2-marin.json). The methods' fits are held against a pinned
// run (kvlcc2_marin_baseline.json): a drop fails, a gain passes (and asks to be pinned).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/csv_dataset.h"
#include "core/json_file.h"
#include "metrics/zigzag_response.h"
#include "tests/apps/run_usvid.h"

namespace usvid {
namespace {

namespace fs = std::filesystem;
using testing::FreshTempDir;
using testing::RunUsvid;

const std::string kData = std::string(USVID_SHARED_DATA_DIR) + "/kvlcc2-marin/";

class Kvlcc2MarinTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!fs::exists(kData)) GTEST_SKIP() << "shared data absent: " << kData;
    dir_ = FreshTempDir();
  }
  // The MARIN file `name` (zz_20, zz_-20, tc_35) imported to a data CSV (docs/data.md).
  std::string Import(const std::string& name) {
    const std::string out = (dir_ / (name + ".csv")).string();
    const auto r = RunUsvid("import --format marin-dat --data " + kData + "MARIN_FREE_KVLCC2_" +
                            name + "_m.dat --out " + out);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return out;
  }
  // First overshoot [deg] of the closed-loop zig-zag `spec` on kvlcc2 at the tests' 91.7 rpm.
  double SimulatedFirstOvershoot(const std::string& spec, const std::string& extra = "") {
    const std::string out = (dir_ / "sim.csv").string();
    const auto r = RunUsvid("simulate --vessel kvlcc2 --maneuver " + spec + " --duration 250 " +
                            extra + " --out " + out);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    const nlohmann::json truth = ReadJsonFile((dir_ / "sim.truth.json").string());
    return truth.at("maneuver").at("report").at("first_overshoot_deg").get<double>();
  }
  fs::path dir_;
};

// The measured 20/-20 zig-zags (ITTC sign: +20 turns to port first). Their reversals were ordered
// about 0 deg, the course ordered, while the ship was 0.56 and 1.12 deg off it at the execute:
// read about that course (metrics/zigzag_response.h), the first overshoot is 15.1 deg to port
// and 13.7 deg to starboard; the single-screw ship turns further to port. (Read about the
// heading at the execute they were 15.7 and 12.6 deg: docs/compare.md#the-base-course.)
TEST_F(Kvlcc2MarinTest, MeasuredZigzagOvershoots) {
  const ZigzagResponse port = AnalyseZigzag(ReadDatasetCsv(Import("zz_20")), 20.0);
  EXPECT_EQ(port.first_turn, -1);
  EXPECT_NEAR(port.base_offset_deg, -0.54, 0.05);
  EXPECT_NEAR(port.overshoot_deg.at(0), 15.14, 0.05);
  EXPECT_NEAR(port.overshoot_deg.at(1), 13.26, 0.05);
  const ZigzagResponse starboard = AnalyseZigzag(ReadDatasetCsv(Import("zz_-20")), 20.0);
  EXPECT_EQ(starboard.first_turn, 1);
  EXPECT_NEAR(starboard.base_offset_deg, -1.10, 0.05);
  EXPECT_NEAR(starboard.overshoot_deg.at(0), 13.67, 0.05);
  EXPECT_NEAR(starboard.overshoot_deg.at(1), 14.93, 0.05);
}

// The nominal MMG model at the tests' 91.7 rpm runs at 13.5 kn instead of the measured 15.8 kn,
// and its first overshoot is low both ways, 2.8 deg on the mean of the two sides (stated error:
// 2 to 3 deg low). The diagnosis of zig-zag 20/-20 says why: the surge resistance is 0.57 of the
// model's (explaining about three quarters of the error); with it the mean of the first
// overshoots comes within 1 deg of the measured one. On the model so extended, two small further
// causes pass: the propeller turning 3.6 rpm faster than logged (input_bias on rev alone) and a
// gyro-like yaw-rate offset of 1.7e-4 rad/s (docs/real-data.md). The model's sides differ more
// than the ship's: 3.2 deg between its first overshoots, against the ship's 1.5 (its flow
// straightening, gamma_R 0.395 and 0.640 either side, is the asymmetry it has).
TEST_F(Kvlcc2MarinTest, NominalFirstOvershootAndTheDiagnosisOfWhy) {
  constexpr double kPort = 15.14, kStarboard = 13.67;  // measured, above
  const double nominal_port = SimulatedFirstOvershoot("zigzag:-20/20");
  const double nominal_starboard = SimulatedFirstOvershoot("zigzag:20/20");
  EXPECT_NEAR((nominal_port + nominal_starboard) / 2 - (kPort + kStarboard) / 2, -2.8, 0.5);
  EXPECT_GT(nominal_port - nominal_starboard, kPort - kStarboard + 1.0);

  const std::string out = (dir_ / "diagnosis").string();
  const auto r = RunUsvid("diagnose --data " + Import("zz_20") + " --vessel kvlcc2 --out " + out);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json d = ReadJsonFile(out + "/diagnosis.json");
  ASSERT_EQ(d.at("cause"), "resistance") << d.at("candidates").dump(1);
  const double scale = d.at("candidates").at(0).at("parameters").at("scale").get<double>();
  EXPECT_NEAR(scale, 0.57, 0.03);
  EXPECT_GT(d.at("candidates").at(0).at("explained").get<double>(), 0.65);
  EXPECT_NEAR(d.at("gain").at("heldout_error_reduction").get<double>(), 0.58, 0.05);
  EXPECT_EQ(d.at("causes"), nlohmann::json({"resistance", "input_bias", "sensor_bias"}));
  EXPECT_EQ(d.at("further_causes").at(0).at("inputs"), nlohmann::json({"rev"}));
  EXPECT_TRUE(d.at("unexplained_residual").get<bool>());  // 26 % is left: see docs

  const std::string effect = "--effect resistance=" + std::to_string(scale);
  EXPECT_NEAR((SimulatedFirstOvershoot("zigzag:-20/20", effect) +
               SimulatedFirstOvershoot("zigzag:20/20", effect)) /
                  2,
              (kPort + kStarboard) / 2, 1.0);
}

// Fits of r and psi [%] per (method, test maneuver), over its cells (the seeds: gp has three).
using Fits = std::map<std::pair<std::string, std::string>, std::vector<std::pair<double, double>>>;

Fits FitsOf(const nlohmann::json& rows) {
  // A diverged free run's fit is -inf, which JSON holds as null.
  auto fit = [](const nlohmann::json& v) { return v.is_null() ? -INFINITY : v.get<double>(); };
  Fits fits;
  for (const auto& row : rows) {
    if (row.at("status") != "ok") continue;  // a failed fit has no fits (checked above)
    const auto& c = row.at("channel_fit_percent");
    fits[{row.at("method"), row.at("test_maneuver")}].emplace_back(fit(c.at("r")),
                                                                   fit(c.at("psi")));
  }
  return fits;
}

double Median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

// Every method trained on zig-zag 20/-20, free-run on the two other tests, against the pinned
// run with `compare --baseline`'s pairing (vessel, maneuvers, method, noise, seed) but one-sided
// and per cell group, since one or three seeds are too few for its signed-rank test: for r and
// psi, the median over the group's seeds and its best seed may each fall at most kTolerance
// points below the pinned run's (the deterministic methods repeat to the last digit; GP's
// search follows the last bit of its sums, and a compiler or library may move a seed). Gains
// pass, with a note to pin them (tools/pin-baseline.py).
TEST_F(Kvlcc2MarinTest, MethodsOnTheHeldOutManeuvers) {
  constexpr double kTolerance = 3.0;
  const std::string out = (dir_ / "study").string();
  const std::string baseline_file =
      std::string(USVID_SOURCE_DIR) + "/tests/real_data/kvlcc2_marin_baseline.json";
  const auto r =
      RunUsvid("compare --suite " + std::string(USVID_SOURCE_DIR) +
               "/docs/studies/kvlcc2-marin.json --baseline " + baseline_file + " --out " + out);
  ASSERT_EQ(r.exit_code, 0) << "compare --baseline found a worse group: " << r.err;
  const nlohmann::json results = ReadJsonFile(out + "/results.json");
  std::map<std::pair<std::string, std::string>, double> mean_fit, first_overshoot_error;
  for (const auto& row : results.at("rows")) {
    ASSERT_EQ(row.at("status"), "ok") << row.dump();
    mean_fit[{row.at("method"), row.at("test_maneuver")}] = row.at("mean_fit_percent");
    if (row.at("test_maneuver") == "zigzag -20/20")
      first_overshoot_error[{row.at("method"), row.at("seed").dump()}] =
          std::abs(row.at("closed_loop").at("first_overshoot_error_deg").get<double>());
  }
  // Issue 38: u', logged to three digits, is noise to every candidate term in the derivatives;
  // SINDy falls back to the weak form over one hull length of travel, which keeps terms in all
  // three equations, and its closed-loop first overshoot on the held-out zig-zag is closer
  // than the published MMG model's (0.50 against 3.82 deg; docs/real-data.md).
  EXPECT_LT(first_overshoot_error.at({"sindy", "1"}), first_overshoot_error.at({"nominal", "1"}));
  // The hybrid (refit plus the u^2-scaled yaw moment it finds on zz_20) is above refit on both
  // held-out tests: 89.0 against 83.9 on the other zig-zag, 83.6 against 82.1 on the turning
  // circle (docs/real-data.md).
  for (const char* test : {"zigzag -20/20", "turning 35"})
    EXPECT_GT(mean_fit.at({"hybrid", test}), mean_fit.at({"refit", test}) + 1.0) << test;

  const Fits now = FitsOf(results.at("rows"));
  const Fits pinned = FitsOf(ReadJsonFile(baseline_file).at("rows"));
  std::vector<std::string> gains;
  for (const auto& [group, base] : pinned) {
    const auto& [method, test] = group;
    ASSERT_TRUE(now.contains(group)) << method << " on " << test << " is missing";
    const auto& cells = now.at(group);
    ASSERT_EQ(cells.size(), base.size()) << method << " on " << test;
    for (const bool psi : {false, true}) {
      std::vector<double> a, b;
      for (const auto& c : cells) a.push_back(psi ? c.second : c.first);
      for (const auto& c : base) b.push_back(psi ? c.second : c.first);
      const std::string what = method + " on " + test + (psi ? ": psi" : ": r");
      const double median_now = Median(a), median_pinned = Median(b);
      const double best_now = *std::max_element(a.begin(), a.end()),
                   best_pinned = *std::max_element(b.begin(), b.end());
      EXPECT_GE(median_now, median_pinned - kTolerance) << what << ", median over the seeds";
      EXPECT_GE(best_now, best_pinned - kTolerance) << what << ", best seed";
      if (median_now > median_pinned + kTolerance) gains.push_back(what);
    }
  }
  for (const std::string& g : gains)
    std::cerr << "gain over the pinned run: " << g << " (pin it: tools/pin-baseline.py)\n";
}

}  // namespace
}  // namespace usvid
