// The KVLCC2 free-running model tests (MARIN, SIMMAN 2008; ../shared/data/kvlcc2-marin) through
// the binary, as docs/real-data.md reports them: the measured zig-zag overshoots, the nominal
// MMG model's first overshoot and why it is low (the diagnosis: the surge resistance), and every
// method trained on zig-zag 20/-20 and scored in free run on zig-zag -20/20 and the 35 deg
// turning circle (docs/studies/kvlcc2-marin.json). The numbers are pinned: a change in any
// method shows here.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

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

// The measured 20/-20 zig-zags (ITTC sign: +20 turns to port first): first overshoot 15.7 deg to
// port, 12.6 deg to starboard; the single-screw ship is not symmetric.
TEST_F(Kvlcc2MarinTest, MeasuredZigzagOvershoots) {
  const ZigzagResponse port = AnalyseZigzag(ReadDatasetCsv(Import("zz_20")), 20.0);
  EXPECT_EQ(port.first_turn, -1);
  EXPECT_NEAR(port.overshoot_deg.at(0), 15.67, 0.05);
  EXPECT_NEAR(port.overshoot_deg.at(1), 12.73, 0.05);
  const ZigzagResponse starboard = AnalyseZigzag(ReadDatasetCsv(Import("zz_-20")), 20.0);
  EXPECT_EQ(starboard.first_turn, 1);
  EXPECT_NEAR(starboard.overshoot_deg.at(0), 12.58, 0.05);
  EXPECT_NEAR(starboard.overshoot_deg.at(1), 16.02, 0.05);
}

// The nominal MMG model at the tests' 91.7 rpm runs at 13.5 kn instead of the measured 15.8 kn,
// and its first overshoot is 2.5 deg low both ways (stated error: 2 to 3 deg low). The
// diagnosis of zig-zag 20/-20 says why: the surge resistance is 0.57 of the model's
// (explaining about three quarters of the error); with it the first overshoots come within
// 1 deg of the measured ones. On the model so extended, two small further causes pass: the
// propeller turning 3.6 rpm faster than logged (input_bias on rev alone) and a gyro-like
// yaw-rate offset of 1.7e-4 rad/s (docs/real-data.md).
TEST_F(Kvlcc2MarinTest, NominalFirstOvershootAndTheDiagnosisOfWhy) {
  const double nominal_port = SimulatedFirstOvershoot("zigzag:-20/20");
  const double nominal_starboard = SimulatedFirstOvershoot("zigzag:20/20");
  EXPECT_NEAR(nominal_port - 15.67, -2.5, 0.5);
  EXPECT_NEAR(nominal_starboard - 12.58, -2.5, 0.5);

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
  EXPECT_NEAR(SimulatedFirstOvershoot("zigzag:-20/20", effect), 15.67, 1.0);
  EXPECT_NEAR(SimulatedFirstOvershoot("zigzag:20/20", effect), 12.58, 1.0);
}

// Every method trained on zig-zag 20/-20, free-run on the two other tests: fit % of r and psi.
TEST_F(Kvlcc2MarinTest, MethodsOnTheHeldOutManeuvers) {
  const std::string out = (dir_ / "study").string();
  const auto r = RunUsvid("compare --suite " + std::string(USVID_SOURCE_DIR) +
                          "/docs/studies/kvlcc2-marin.json --out " + out);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json results = ReadJsonFile(out + "/results.json");
  // method, test -> fits of r and psi over the seeds (one seed but for gp), and the mean fit of
  // u, v and r.
  std::map<std::pair<std::string, std::string>, std::vector<std::pair<double, double>>> fits;
  std::map<std::pair<std::string, std::string>, double> mean_fit;
  for (const auto& row : results.at("rows")) {
    ASSERT_EQ(row.at("status"), "ok") << row.dump();
    const auto& c = row.at("channel_fit_percent");
    fits[{row.at("method"), row.at("test_maneuver")}].emplace_back(c.at("r"), c.at("psi"));
    mean_fit[{row.at("method"), row.at("test_maneuver")}] = row.at("mean_fit_percent");
  }
  // The hybrid (refit plus the u^2-scaled yaw moment it finds on zz_20) is above refit on both
  // held-out tests: 88.9 against 83.9 on the other zig-zag, 83.6 against 82.1 on the turning
  // circle (docs/real-data.md).
  for (const char* test : {"zigzag -20/20", "turning 35"})
    EXPECT_GT(mean_fit.at({"hybrid", test}), mean_fit.at({"refit", test}) + 1.0) << test;
  struct Pin {
    const char* method;
    const char* test;
    double r, psi;
  };
  const Pin pins[] = {
      {"nominal", "zigzag -20/20", 82.9, 51.7},      {"nominal", "turning 35", 81.4, 94.0},
      {"diagnose", "zigzag -20/20", 87.3, 40.9},     {"diagnose", "turning 35", 80.3, 92.2},
      {"refit", "zigzag -20/20", 86.5, 45.2},        {"refit", "turning 35", 85.1, 97.6},
      {"hybrid", "zigzag -20/20", 93.9, 96.2},       {"hybrid", "turning 35", 88.2, 95.5},
      {"fossen-ceres", "zigzag -20/20", 87.6, 63.9}, {"fossen-ceres", "turning 35", 68.7, 78.3},
      {"sindy", "zigzag -20/20", 49.9, 42.8},        {"sindy", "turning 35", 43.9, 67.7},
  };
  for (const Pin& p : pins) {
    const auto& f = fits.at({p.method, p.test});
    ASSERT_EQ(f.size(), 1u) << p.method;
    EXPECT_NEAR(f[0].first, p.r, 1.0) << p.method << " on " << p.test << ": r";
    EXPECT_NEAR(f[0].second, p.psi, 1.0) << p.method << " on " << p.test << ": psi";
  }
  // GP at its defaults: the median over its three seeds on the other zig-zag; on the turning
  // circle, two of the three seeds diverge (a 35 deg turn lies outside what one zig-zag shows)
  // and the third fits r to 70.5 %.
  auto median = [](std::vector<double> v) {
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
  };
  const auto& zigzag = fits.at({"gp[+,-,*,abs]", "zigzag -20/20"});
  ASSERT_EQ(zigzag.size(), 3u);
  std::vector<double> rs, psis;
  for (const auto& [a, b] : zigzag) rs.push_back(a), psis.push_back(b);
  EXPECT_NEAR(median(rs), 75.3, 3.0) << "gp on the zig-zag: r";
  EXPECT_NEAR(median(psis), 83.0, 3.0) << "gp on the zig-zag: psi";
  const auto& turning = fits.at({"gp[+,-,*,abs]", "turning 35"});
  ASSERT_EQ(turning.size(), 3u);
  double best_r = -INFINITY;
  for (const auto& [a, b] : turning) best_r = std::max(best_r, a);
  EXPECT_NEAR(best_r, 70.5, 3.0) << "gp on the turning circle: the best seed's r";
}

}  // namespace
}  // namespace usvid
