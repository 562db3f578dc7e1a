// `--vessel FILE` as a user runs it (docs/model.md#vessel-files): a ship given by its
// particulars simulates a zig-zag, the refit recovers a yaw damping hidden in a record of it
// through the same Jet-differentiated simulator as the compiled-in vessels, a particular is not
// a fit parameter, and a bad file stops the command with exit code 2, naming file:line and the
// key, and writing nothing.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

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
  EXPECT_THAT(r.err, HasSubstr("40 coefficients not given, estimated from the particulars"));
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
  EXPECT_EQ(ReadJsonFile((dir / "vessel" / "vessel.json").string()).at("estimated").size(), 40u);
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
