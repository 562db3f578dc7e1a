// A log that names its maneuver (HSVA's header, kept in F.record.json) as a user meets it
// (issue 69): `usvid info --zigzag` reads the test as the name says; a name the record
// contradicts, or one usvid does not know, is exit 2 with one line naming the file and what is
// wrong, in `info` and in a suite that tests on the record.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "tests/apps/run_usvid.h"

namespace usvid {
namespace {

using testing::FreshTempDir;
using ::testing::HasSubstr;
using ::testing::Not;
using testing::RunUsvid;
namespace fs = std::filesystem;

class NamedManeuverCliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string log =
        std::string(USVID_SHARED_DATA_DIR) + "/kvlcc2-hsva/HSVA_CPMC_KVLCC2_Z_20_10_S.dat";
    if (!fs::exists(log)) GTEST_SKIP() << "shared data absent: " << log;
    dir_ = FreshTempDir();
    const auto r = RunUsvid("import --format hsva-dat --data " + log + " --scale 45.7 --out " +
                            (dir_ / "zz.csv").string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  // The record's maneuver renamed, as a wrong header would name it.
  void Name(const std::string& maneuver) {
    testing::WriteText(dir_ / "zz.record.json", "{\"maneuver\": \"" + maneuver + "\"}\n");
  }
  fs::path dir_;
};

TEST_F(NamedManeuverCliTest, InfoReadsTheTestAsItsHeaderNamesIt) {
  const auto r = RunUsvid("info --data " + (dir_ / "zz.csv").string() + " --zigzag");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("zig-zag 20/10 (heading check B named by the log ('Z20°/10° "
                               "starting to starboard', checked against the record))"));
  EXPECT_THAT(r.out, HasSubstr("first turn to starboard"));
  // HSVA logs the rudder's angle, moving at the gear's 13 deg/s, 1.9 at full scale: no orders.
  EXPECT_THAT(r.out, HasSubstr("rudder delta: its large moves at 1.9"));
  EXPECT_THAT(r.out, Not(HasSubstr("orders")));
}

TEST_F(NamedManeuverCliTest, AHeaderTheRecordContradictsIsExitTwoNamingTheFile) {
  for (const auto& [name, why] :
       {std::pair{"Z20°/10° starting to port", "the record turns to starboard first"},
        std::pair{"Z20°/20°", "not at B = 20"}, std::pair{"Z35°/10°", "held at 20 deg"}}) {
    Name(name);
    const auto r = RunUsvid("info --data " + (dir_ / "zz.csv").string() + " --zigzag");
    EXPECT_EQ(r.exit_code, 2) << name << ": " << r.err;
    EXPECT_THAT(r.err, HasSubstr((dir_ / "zz.csv").string() + ": the log names its maneuver"));
    EXPECT_THAT(r.err, HasSubstr(why)) << name;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
}

TEST_F(NamedManeuverCliTest, AnUnknownManeuverInAHeaderIsExitTwo) {
  Name("Williamson turn");
  const auto r = RunUsvid("info --data " + (dir_ / "zz.csv").string() + " --zigzag");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_THAT(r.err, HasSubstr("the maneuver 'Williamson turn' is none usvid knows"));
}

TEST_F(NamedManeuverCliTest, ASuiteTestingOnAContradictedRecordStopsBeforeAnyFit) {
  Name("Z20°/10° starting to port");
  testing::WriteText(dir_ / "suite.json", R"({"name": "named", "vessels": ["kvlcc2"],
    "data": {"train": [{"name": "train", "file": "zz.csv"}],
             "test": [{"name": "test", "file": "zz.csv", "maneuver": "zigzag"}]},
    "methods": ["nominal"]})");
  const auto r = RunUsvid("compare --suite " + (dir_ / "suite.json").string() + " --out " +
                          (dir_ / "out").string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_THAT(r.err, HasSubstr("the record turns to starboard first"));
  EXPECT_FALSE(fs::exists(dir_ / "out" / "results.json"));
}

}  // namespace
}  // namespace usvid
