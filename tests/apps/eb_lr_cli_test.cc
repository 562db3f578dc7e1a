// Eriksen & Breivik's step grid and eb-lr through the binary (issue 70): a step grid whose fixed
// hold is too short for any steady window is exit 2 at `usvid simulate` and when a suite is read,
// one line naming the hold and the time a step needs, and nothing is written; a record with no
// steady state at all is one line of eb-lr's.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "tests/apps/run_usvid.h"

namespace usvid {
namespace {

using testing::FreshTempDir;
using ::testing::HasSubstr;
using testing::RunUsvid;
using testing::WriteText;
namespace fs = std::filesystem;

class EbLrCliTest : public ::testing::Test {};

// simulate: exit 2, the hold (5 s) and the 8 s a step needs named on one line, no data file.
TEST_F(EbLrCliTest, HoldTooShortIsExitTwoAtSimulate) {
  const auto dir = FreshTempDir();
  const auto out = (dir / "grid.csv").string();
  const auto r = RunUsvid("simulate --vessel odin-hs --maneuver stepgrid:4/3/5 --out " + out);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_THAT(r.err, HasSubstr("a hold of 5 s is too short for any steady window"));
  EXPECT_THAT(r.err, HasSubstr("at least 8 s"));
  EXPECT_FALSE(fs::exists(out));
}

// A suite training (or testing) on such a grid is refused when it is read, before any fit.
TEST_F(EbLrCliTest, HoldTooShortIsExitTwoInASuite) {
  const auto dir = FreshTempDir();
  const auto suite = (dir / "suite.json").string();
  WriteText(suite, nlohmann::json{{"name", "short-hold"},
                                  {"vessels", {"odin3dof"}},
                                  {"train_maneuvers", {"stepgrid:2/1/6"}},
                                  {"test_maneuvers", {"random-steps"}},
                                  {"methods", {"eb-lr"}},
                                  {"seeds", {1}}}
                       .dump());
  const auto out = dir / "run";
  const auto r = RunUsvid("compare --suite " + suite + " --out " + out.string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_THAT(r.err, HasSubstr("train_maneuvers"));
  EXPECT_THAT(r.err, HasSubstr("a hold of 6 s is too short for any steady window"));
  EXPECT_FALSE(fs::exists(out / "results.json"));
}

// A multisine holds no input: eb-lr's row (here usvid identify's error) says so in one line.
TEST_F(EbLrCliTest, NoSteadyStateIsOneLine) {
  const auto dir = FreshTempDir();
  const auto data = (dir / "ms.csv").string();
  ASSERT_EQ(RunUsvid("simulate --vessel eb2dof --maneuver multisine --duration 120 --out " + data)
                .exit_code,
            0);
  const auto r = RunUsvid("identify --method eb-lr --vessel eb2dof --data " + data + " --out " +
                          (dir / "m.json").string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_THAT(r.err, HasSubstr("found 0 steady windows: the record has no steady state"));
}

}  // namespace
}  // namespace usvid
