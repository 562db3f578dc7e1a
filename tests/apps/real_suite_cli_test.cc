// `usvid compare --suite NAME` and the real suite's data folder as a user meets them (issue 40):
// an unknown name and a folder without the expected files are exit 2 naming them, with nothing
// written; a missing folder is a skip (exit 0) that says so.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "tests/apps/run_usvid.h"

namespace usvid {
namespace {

using testing::FreshTempDir;
using ::testing::HasSubstr;
using testing::RunUsvid;
namespace fs = std::filesystem;

TEST(RealSuiteCliTest, AnUnknownSuiteNameIsRefusedNamingTheEmbeddedOnes) {
  const fs::path dir = FreshTempDir();
  const auto r = RunUsvid("compare --suite realistc --out " + (dir / "out").string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_THAT(
      r.err,
      HasSubstr(
          "'realistc' is no embedded suite (default, quick, realistic, realistic-measured, eb2dof, real)"));
  EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(RealSuiteCliTest, AMissingDataFolderIsASkipThatSaysSo) {
  const fs::path dir = FreshTempDir();
  const auto r = RunUsvid("compare --suite real --data-dir " + (dir / "absent").string() +
                          " --out " + (dir / "out").string());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("suite 'real' skipped: no data folder"));
  EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(RealSuiteCliTest, AFolderWithoutTheExpectedFilesIsRefusedNamingThem) {
  const fs::path dir = FreshTempDir();
  fs::create_directories(dir / "data" / "kvlcc2-marin");
  testing::WriteText(dir / "data" / "kvlcc2-marin" / "MARIN_FREE_KVLCC2_zz_20_m.dat", "x\n");
  const auto r = RunUsvid("compare --suite real --data-dir " + (dir / "data").string() + " --out " +
                          (dir / "out").string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_THAT(r.err, HasSubstr("lacks kvlcc2-marin/MARIN_FREE_KVLCC2_zz_-20_m.dat, "
                               "kvlcc2-marin/MARIN_FREE_KVLCC2_tc_35_m.dat, esso-osaka/ (all"));
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;  // one line
  EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(RealSuiteCliTest, BaselineWithTheRealSuiteIsRefused) {
  const fs::path dir = FreshTempDir();
  const auto r = RunUsvid("compare --suite real --baseline x.json --out " + (dir / "out").string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_THAT(r.err, HasSubstr("--baseline compares one suite"));
}

}  // namespace
}  // namespace usvid
