// `usvid vessel`: the characterisation of odin-hs shows the three regimes (issue 3 acceptance):
// steady speeds from displacement through semi-displacement to planing as the throttle rises,
// resistance with a hump, and the plots a person looks at.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include "core/json_file.h"
#include "tests/apps/run_usvid.h"

namespace usvid {
namespace {

using testing::FreshTempDir;
using testing::RunUsvid;
namespace fs = std::filesystem;

class VesselCliTest : public ::testing::Test {};

TEST_F(VesselCliTest, OdinHsShowsThreeRegimes) {
  const auto dir = FreshTempDir();
  const auto r = RunUsvid("vessel --vessel odin-hs --points 11 --out " + dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* f : {"steady_speed.svg", "turning_radius.svg", "resistance.svg", "froude.svg"})
    EXPECT_TRUE(fs::exists(dir / f)) << f;
  const nlohmann::json v = ReadJsonFile((dir / "vessel.json").string());
  std::vector<std::string> regimes;
  double last_speed = 0.0;
  for (const auto& row : v.at("steady")) {
    EXPECT_TRUE(row.at("settled").get<bool>());
    EXPECT_GT(row.at("speed").get<double>(), last_speed);  // faster with more throttle
    last_speed = row.at("speed").get<double>();
    regimes.push_back(row.at("regime"));
  }
  EXPECT_EQ(regimes.front(), "displacement");
  EXPECT_EQ(regimes.back(), "planing");
  EXPECT_EQ(std::set<std::string>(regimes.begin(), regimes.end()).size(), 3u);
  // The resistance hump: R rises to a local maximum in semi-displacement, then falls.
  const auto& res = v.at("resistance");
  bool hump = false;
  for (size_t k = 1; k + 1 < res.size(); ++k) {
    const double a = res[k - 1].at("resistance_n"), b = res[k].at("resistance_n"),
                 c = res[k + 1].at("resistance_n");
    const double fn = res[k].at("froude");
    if (b > a && b > c) hump = hump || (fn > 0.4 && fn < 1.1);
  }
  EXPECT_TRUE(hump);
}

}  // namespace
}  // namespace usvid
