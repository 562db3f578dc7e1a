// The `usvid` binary as a user runs it: help, version, exit codes, import and info.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "core/csv_dataset.h"
#include "tests/apps/run_usvid.h"

namespace usvid {
namespace {

using testing::FreshTempDir;
using ::testing::HasSubstr;
using ::testing::Not;
using testing::RunUsvid;
using ::testing::StartsWith;
using testing::WriteText;
namespace fs = std::filesystem;

class UsvidCliTest : public ::testing::Test {};

// --help lists the subcommands; --version names the program; both exit 0.
TEST_F(UsvidCliTest, HelpAndVersion) {
  const auto help = RunUsvid("--help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_THAT(help.out, HasSubstr("import"));
  EXPECT_THAT(help.out, HasSubstr("info"));
  const auto sub = RunUsvid("import --help");
  EXPECT_EQ(sub.exit_code, 0);
  EXPECT_THAT(sub.out, HasSubstr("--map"));
  const auto version = RunUsvid("--version");
  EXPECT_EQ(version.exit_code, 0);
  EXPECT_THAT(version.out, StartsWith("usvid "));
}

// Usage errors exit 2 with one line naming the command or option (docs/data.md#command-line).
TEST_F(UsvidCliTest, UsageErrorsExitTwo) {
  const auto none = RunUsvid("");
  EXPECT_EQ(none.exit_code, 2);
  const auto unknown = RunUsvid("fly");
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_THAT(unknown.err, HasSubstr("unknown command 'fly'"));
  const auto format = RunUsvid("import --format xls --data a --out b");
  EXPECT_EQ(format.exit_code, 2);
  EXPECT_THAT(format.err, HasSubstr("--format"));
  const auto missing = RunUsvid("info --data /nonexistent/x.csv");
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_THAT(missing.err, HasSubstr("/nonexistent/x.csv"));
}

// The options added for measured data refuse what they cannot do: exit 2, the option or file
// named, no output left.
TEST_F(UsvidCliTest, MeasuredDataOptionsRefuseBadInput) {
  const auto dir = FreshTempDir();
  const std::string data = (dir / "k.csv").string();
  ASSERT_EQ(RunUsvid("simulate --vessel kvlcc2 --maneuver zigzag:20/20 --duration 60 --out " + data)
                .exit_code,
            0);
  struct Case {
    std::string args, says;
  };
  const std::string out = (dir / "out").string();
  WriteText(dir / "suite.json",
            R"({"vessels": ["kvlcc2"], "methods": ["nominal"], "data": {"train": [{"name": "a",
            "file": "missing.csv"}], "test": [{"name": "b", "file": "missing.csv"}]}})");
  WriteText(dir / "log.csv", "time,yaw\n0,0\n1,0.1\n2,0.2\n3,0.3\n4,0.4\n");
  WriteText(dir / "effects.json", R"({"effects": [{"effect": "current", "parameters": {}}]})");
  const Case cases[] = {
      {"simulate --vessel kvlcc2 --maneuver zigzag:20/20 --cruise 500 --out " + out + ".csv",
       "--cruise"},
      {"simulate --vessel odin3dof --maneuver zigzag:0/20 --out " + out + ".csv", "zigzag"},
      {"simulate --vessel kvlcc2 --maneuver zigzag:20/20 --params " +
           (dir / "effects.json").string() + " --out " + out + ".csv",
       "effects.json"},
      {"identify --method refit --data " + data + " --out " + out + ".json", "needs --vessel"},
      {"identify --method refit --vessel kvlcc2 --refit-params R_0,Z_zz --data " + data +
           " --out " + out + ".json",
       "Z_zz"},
      {"identify --method nomoto --states r,u --inputs delta --data " + data + " --out " + out +
           ".json",
       "nomoto"},
      {"info --data " + data + " --zigzag -5", "--zigzag"},
      {"info --data " + data + " --zigzag 20 --rudder flap", "flap"},
      {"diagnose --data " + data + " --vessel kvlcc2 --causes 0 --out " + out, "--causes"},
      {"compare --suite " + (dir / "suite.json").string() + " --out " + out, "missing.csv"},
      {"import --format csv --data " + (dir / "log.csv").string() +
           " --map t=time,psi=yaw --rate-from heading --out " + out + ".csv",
       "heading"},
      {"import --format csv --data " + (dir / "log.csv").string() +
           " --map t=time,psi=yaw --rate-bias-from psi --out " + out + ".csv",
       "no rate of turn column 'r'"},
      {"import --format csv --data " + (dir / "log.csv").string() +
           " --map t=time,psi=yaw --end-at-stop rpm --out " + out + ".csv",
       "no column 'rpm' to end the record at"},
  };
  for (const Case& c : cases) {
    const auto r = RunUsvid(c.args);
    EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.err;
    EXPECT_THAT(r.err, HasSubstr(c.says)) << c.args;
    EXPECT_FALSE(fs::exists(out + ".csv") || fs::exists(out + ".json") ||
                 fs::exists(out + "/diagnosis.json") || fs::exists(out + "/results.json"))
        << c.args;
  }
}

// A malformed data file: exit 2, "file:line:column: what" on stderr.
TEST_F(UsvidCliTest, MalformedCsvIsLocated) {
  const auto dir = FreshTempDir();
  WriteText(dir / "bad.csv", "t,u\n0,1\n0.1,nan\n");
  const auto r = RunUsvid("info --data " + (dir / "bad.csv").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr((dir / "bad.csv").string() + ":3:5: column 'u'"));
}

// A foreign CSV log imports with a map and passes `usvid info`'s check; a bad log leaves no
// output file behind.
TEST_F(UsvidCliTest, ImportCsvThenInfo) {
  const auto dir = FreshTempDir();
  WriteText(dir / "log.csv", "time,heading_deg,speed_kn\n0,10,2\n0.5,11,2.1\n0.5,11,2.1\n1,12,2\n");
  const auto out = (dir / "data.csv").string();
  const auto r = RunUsvid("import --format csv --data " + (dir / "log.csv").string() +
                          " --map t=time,psi=heading_deg:deg,U=speed_kn:knots --out " + out);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("dropping 1 rows"));
  const Dataset d = ReadDatasetCsv(out);
  EXPECT_EQ(d.rows(), 3);
  EXPECT_NEAR(d["U"](0), 2 * 0.514444, 1e-5);
  EXPECT_EQ(RunUsvid("info --data " + out).exit_code, 0);

  WriteText(dir / "bad.csv", "time,x\n0,1\n1,x\n");
  const auto bad_out = (dir / "bad_out.csv").string();
  const auto bad = RunUsvid("import --format csv --data " + (dir / "bad.csv").string() +
                            " --map t=time,x=x --out " + bad_out);
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_THAT(bad.err, HasSubstr("bad.csv:3:3"));
  EXPECT_FALSE(fs::exists(bad_out));
}

// A log whose propeller stops before its end: info says where and how long the record goes on,
// and import --end-at-stop drops those rows and says so (docs/data.md#the-end-of-a-test).
TEST_F(UsvidCliTest, ThePropellersStopIsReportedAndTheRecordCanEndThere) {
  const auto dir = FreshTempDir();
  WriteText(dir / "log.csv", "time,rps,yaw\n0,10,0\n1,10,0.1\n2,10,0.2\n3,0,0.5\n4,0,0.1\n");
  const auto whole = (dir / "whole.csv").string(), test = (dir / "test.csv").string();
  ASSERT_EQ(RunUsvid("import --format csv --data " + (dir / "log.csv").string() +
                     " --map t=time,n=rps,psi=yaw --out " + whole)
                .exit_code,
            0);
  const auto info = RunUsvid("info --data " + whole);
  EXPECT_THAT(info.out, HasSubstr("n stops at 2.0 s and the record goes on for 2.0 s"));
  const auto r = RunUsvid("import --format csv --data " + (dir / "log.csv").string() +
                          " --map t=time,n=rps,psi=yaw --end-at-stop n --out " + test);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("ended where n stopped, at t = 2.0 s: 2.0 s (2 rows) dropped"));
  EXPECT_EQ(ReadDatasetCsv(test).rows(), 3);
  EXPECT_THAT(RunUsvid("info --data " + test).out, Not(HasSubstr("stops at")));
}

// --scale Froude-scales the log and says each channel's factor; a scale of 0 or below, or a
// channel of no known dimension, is exit 2 with one line and no file written.
TEST_F(UsvidCliTest, ImportFroudeScales) {
  const auto dir = FreshTempDir();
  WriteText(dir / "log.csv", "t,u,r,n,delta,wind\n10,0.5,0.1,10,0.2,1\n10.1,0.6,0.2,11,0.3,2\n");
  const auto out = (dir / "full.csv").string();
  const std::string args = "import --format csv --data " + (dir / "log.csv").string() +
                           " --map t=t,u=u,r=r,n=n,delta=delta,wind=wind --out " + out;
  const auto r = RunUsvid(args + " --scale 100 --dimension wind=speed");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("Froude-scaled by lambda = 100: t x10, u x10 (speed)"));
  const Dataset d = ReadDatasetCsv(out);
  EXPECT_NEAR(d.t()(0), 100.0, 1e-9);  // time may start anywhere, and scales with the rest
  EXPECT_NEAR(d.t()(1), 101.0, 1e-9);
  EXPECT_NEAR(d["u"](0), 5.0, 1e-12);
  EXPECT_NEAR(d["r"](0), 0.01, 1e-12);
  EXPECT_NEAR(d["n"](1), 1.1, 1e-12);
  EXPECT_NEAR(d["delta"](0), 0.2, 1e-12);
  EXPECT_NEAR(d["wind"](1), 20.0, 1e-12);
  fs::remove(out);
  for (const char* bad : {" --scale 0", " --scale -4", " --scale 100"}) {
    const auto e = RunUsvid(args + bad);
    EXPECT_EQ(e.exit_code, 2) << bad;
    EXPECT_THAT(e.err, HasSubstr("--scale")) << bad;
    EXPECT_EQ(std::count(e.err.begin(), e.err.end(), '\n'), 1) << e.err;
    EXPECT_FALSE(fs::exists(out)) << bad;
  }
  EXPECT_THAT(RunUsvid(args + " --scale 100").err,
              HasSubstr("channel 'wind' has no known dimension"));
}

// The KVLCC2 acceptance command of issue 2, run through the binary.
TEST_F(UsvidCliTest, ImportMarinZigZag) {
  const std::string path =
      std::string(USVID_SHARED_DATA_DIR) + "/kvlcc2-marin/MARIN_FREE_KVLCC2_zz_20_m.dat";
  if (!fs::exists(path)) GTEST_SKIP() << "shared data absent: " << path;
  const auto dir = FreshTempDir();
  const auto out = (dir / "k.csv").string();
  const auto r = RunUsvid("import --format marin-dat --data " + path + " --out " + out);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("repaired 3235 rows"));
  const Dataset d = ReadDatasetCsv(out);  // strictly increasing t, or this throws
  EXPECT_NEAR(d["u"](0), 8.1, 0.05);
  EXPECT_LT(d["v"].cwiseAbs().maxCoeff(), 2.0);
}

}  // namespace
}  // namespace usvid
