// The small USV's GPS zig-zag (../shared/data/usv-fuzhou, 2 Hz, no gyro) through the binary, as
// docs/real-data.md reports it: the rate of turn from the heading, a first-order Nomoto model
// (T r' + r = K (delta - delta0)) and GP and SINDy trained on the first 140 s and free-run on
// the last 70 s (docs/studies/usv-fuzhou.json).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "core/json_file.h"
#include "tests/apps/run_usvid.h"

namespace usvid {
namespace {

namespace fs = std::filesystem;
using testing::FreshTempDir;
using testing::RunUsvid;

const std::string kLog = std::string(USVID_SHARED_DATA_DIR) + "/usv-fuzhou/zigzag_30_inter_xy.csv";

// On the whole log: a rudder to yaw-rate gain and a time constant of a 3.6 m boat (negative K:
// the log's delta is positive to port), and the heading's free run.
TEST(UsvFuzhouTest, NomotoModelOfTheWholeLog) {
  if (!fs::exists(kLog)) GTEST_SKIP() << "shared data absent: " << kLog;
  const fs::path dir = FreshTempDir();
  const std::string data = (dir / "usv.csv").string(), model = (dir / "nomoto.json").string();
  auto r = RunUsvid("import --format csv --data " + kLog +
                    " --map t=time,psi=psi,delta=delta,U=speed --rate-from psi --out " + data);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = RunUsvid("identify --method nomoto --states r --inputs delta --data " + data + " --out " +
               model);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json m = ReadJsonFile(model);
  EXPECT_NEAR(m.at("parameters").at("K").get<double>(), -0.259, 0.01);
  EXPECT_NEAR(m.at("parameters").at("T").get<double>(), 4.26, 0.2);
  r = RunUsvid("evaluate --model " + model + " --data " + data);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json metrics = nlohmann::json::parse(r.out);
  EXPECT_NEAR(metrics.at("psi").at("fit_percent").get<double>(), 72.2, 1.0);
}

// Held out: the last 70 s. The Nomoto model's two constants carry over. SINDy, which must find
// its terms in a 2 Hz derivative of a GPS heading, finds none that beats no term by more than
// the folds' spread, in the derivatives or the weak form; at its defaults it then keeps r's
// linear equation (r, delta and a constant by least squares: Nomoto's form, fitted to the
// derivative rather than by simulation), never "r' = 0" (issue 38), and scores a little below
// Nomoto on r and well below on the heading it integrates. GP's outcome here is
// chaotic: which terms its search keeps changes with the last bit of libm's results, so on one
// machine two seeds of three beat Nomoto and on another none did (docs/real-data.md). The test
// therefore pins only what holds on every machine: each GP seed is scored, with finite fits.
TEST(UsvFuzhouTest, MethodsOnTheHeldBackPart) {
  if (!fs::exists(kLog)) GTEST_SKIP() << "shared data absent: " << kLog;
  const fs::path dir = FreshTempDir();
  const auto r = RunUsvid("compare --suite " + std::string(USVID_SOURCE_DIR) +
                          "/docs/studies/usv-fuzhou.json --out " + (dir / "study").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json results = ReadJsonFile((dir / "study" / "results.json").string());
  std::map<std::string, std::vector<std::pair<double, double>>> fits;
  for (const auto& row : results.at("rows")) {
    ASSERT_EQ(row.at("status"), "ok") << row.dump();
    const auto& c = row.at("channel_fit_percent");
    fits[row.at("method")].emplace_back(c.at("r"), c.at("psi"));
  }
  ASSERT_EQ(fits.at("nomoto").size(), 1u);
  EXPECT_NEAR(fits.at("nomoto")[0].first, 48.3, 1.0);
  EXPECT_NEAR(fits.at("nomoto")[0].second, 75.7, 1.0);
  ASSERT_EQ(fits.at("sindy").size(), 1u);
  EXPECT_NEAR(fits.at("sindy")[0].first, 46.0, 1.0);
  EXPECT_LT(fits.at("sindy")[0].second, fits.at("nomoto")[0].second);
  ASSERT_EQ(fits.at("gp[+,-,*]").size(), 3u);
  for (const auto& [r_fit, psi_fit] : fits.at("gp[+,-,*]"))
    EXPECT_TRUE(std::isfinite(r_fit) && std::isfinite(psi_fit));
}

}  // namespace
}  // namespace usvid
