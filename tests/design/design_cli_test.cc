// `usvid design` through the binary: design.json in the shape (each maneuver's
// parameter_sd, log det, condition number, weakest directions; best), the figure, --optimize
// beating every built-in maneuver of the same length and --check confirming it; bad requests
// exit 2 with one line and leave no output.
#include <gtest/gtest.h>

#include <filesystem>

#include "core/json_file.h"
#include "tests/apps/run_usvid.h"

namespace usvid {
namespace {

using testing::FreshTempDir;
using testing::RunUsvid;

TEST(DesignCliTest, RanksManeuversOptimisesAndChecks) {
  const auto dir = FreshTempDir();
  const std::string out = (dir / "design").string();
  const auto r = RunUsvid(
      "design --vessel odin3dof --method fossen-ceres --maneuvers "
      "random-steps,stepgrid,zigzag,multisine,prbs --duration 600 --optimize --check 8 "
      "--threads 2 --out " +
      out);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(out + "/design.svg"));
  const nlohmann::json d = ReadJsonFile(out + "/design.json");
  double best_built_in = -1e300, best_optimized = -1e300;
  nlohmann::json optimized;
  for (const auto& m : d.at("maneuvers")) {
    EXPECT_EQ(m.at("parameter_sd").size(), 10u);
    EXPECT_TRUE(m.contains("condition_number"));
    EXPECT_FALSE(m.at("weakest_directions").at(0).at("parameters").empty());
    const double log_det = m.at("log_det_information");
    if (m.at("optimized")) {
      if (log_det > best_optimized) optimized = m;
      best_optimized = std::max(best_optimized, log_det);
    } else {
      best_built_in = std::max(best_built_in, log_det);
    }
    EXPECT_EQ(m.at("check").at("failed"), 0) << m.at("maneuver");
  }
  EXPECT_GT(best_optimized, best_built_in);
  EXPECT_EQ(d.at("best"), optimized.at("maneuver"));
  // The fits of the best design scatter as predicted (within a factor of 1.5 either way).
  const double ratio = optimized.at("check").at("median_ratio");
  EXPECT_GE(ratio, 0.67);
  EXPECT_LE(ratio, 1.5);
  EXPECT_EQ(d.dump().find("null"), std::string::npos);
}

TEST(DesignCliTest, RefusesBadRequestsAndWritesNothing) {
  const auto dir = FreshTempDir();
  const std::string out = (dir / "design").string();
  const char* bad[] = {
      "--vessel odin3dof --method gp --maneuvers prbs",
      "--vessel odin3dof --method magic --maneuvers prbs",
      "--vessel kvlcc2 --method fossen-ceres --maneuvers zigzag",
      "--vessel odin3dof --method fossen-ceres --maneuvers warp",
      "--vessel odin3dof --method fossen-ceres --maneuvers prbs --duration 0",
      "--vessel submarine --method refit --maneuvers prbs",
      "--vessel odin3dof --method fossen-ceres --maneuvers prbs --check 1",
      "--vessel odin3dof --method fossen-ceres --maneuvers prbs --parameters Nr,warp",
      "--vessel odin3dof --method eb-lr --maneuvers stepgrid",
  };
  for (const char* args : bad) {
    const auto r = RunUsvid(std::string("design ") + args + " --out " + out);
    EXPECT_EQ(r.exit_code, 2) << args;
    EXPECT_NE(r.err.find("error"), std::string::npos) << args;
    EXPECT_FALSE(std::filesystem::exists(out)) << args;
  }
}

// eb-lr through the binary (eb2dof): the step grid is the best trial eb-lr can fit; the zig-zag
// is listed as unusable with eb-lr's reason and never best; each maneuver eb-lr fits carries a
// shooting fit's sd beside eb-lr's own.
TEST(DesignCliTest, DesignsForEbLr) {
  const auto dir = FreshTempDir();
  const std::string out = (dir / "design").string();
  const auto r = RunUsvid(
      "design --vessel eb2dof --method eb-lr --maneuvers stepgrid,random-steps,zigzag "
      "--duration 600 --parameters sigma_U.U*U,sigma_U.U*U*U --out " + out);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json d = ReadJsonFile(out + "/design.json");
  EXPECT_EQ(d.at("best"), "stepgrid");
  EXPECT_EQ(d.at("parameters_of_interest").size(), 2u);
  const nlohmann::json& zigzag = d.at("maneuvers").at(2);
  EXPECT_FALSE(zigzag.at("usable"));
  EXPECT_NE(zigzag.at("unusable_because").get<std::string>().find("constant"), std::string::npos);
  EXPECT_EQ(d.at("maneuvers").at(0).at("shooting_fit_sd").size(), 11u);
}

}  // namespace
}  // namespace usvid
