// `usvid import --format hsva-dat` as a user runs it: the record's maneuver kept in F.record.json
// beside F.csv and read back with the data, a stale record file removed by a re-import of a log
// without one, a bad log or record file named with its line, and --scale as for marin-dat; on
// the nine shared HSVA zig-zags when ../shared/data is there.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "core/csv_dataset.h"
#include "core/json_file.h"
#include "tests/apps/run_usvid.h"

namespace usvid {
namespace {

using testing::FreshTempDir;
using ::testing::HasSubstr;
using testing::RunUsvid;
using testing::WriteText;
namespace fs = std::filesystem;

const std::string kStarboard = "Z20\xC2\xB0/10\xC2\xB0 starting to starboard";

// An HSVA file as the tank writes it: cp1252 header (0xB0 the degree sign), 12 columns.
std::string HsvaText(int rows) {
  std::string text =
      " HSVA, experimental data CPMC\n KVLCC2\n Z20\xB0/10\xB0 starting to starboard\n"
      " Time series of motions\n";
  for (int k = 0; k < rows; ++k)
    text += "  " + std::to_string(0.05 * k) + "  " + std::to_string(1.2 * 0.05 * k) +
            "  0.0  0.0  1.2  0.0  0.0  0.1  -0.03  10.2295  41.0  1.1\n";
  return text;
}

class ImportHsvaCliTest : public ::testing::Test {};

// The maneuver of the log's header goes to F.record.json (with where, how and at what scale it
// was imported), and every command reading F.csv reads it back; usvid info accepts the file.
TEST_F(ImportHsvaCliTest, WritesTheRecordFileAndReadsItBack) {
  const fs::path dir = FreshTempDir();
  const std::string log = (dir / "run.dat").string(), out = (dir / "run.csv").string();
  WriteText(log, HsvaText(40));
  const auto r = RunUsvid("import --format hsva-dat --data " + log + " --out " + out);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("the maneuver '" + kStarboard + "' kept in " +
                               (dir / "run.record.json").string()));
  const nlohmann::json record = ReadJsonFile((dir / "run.record.json").string());
  EXPECT_EQ(record.at("maneuver"), kStarboard);
  EXPECT_EQ(record.at("imported_from"), log);
  EXPECT_EQ(record.at("format"), "hsva-dat");
  EXPECT_EQ(record.at("scale"), 1.0);
  const Dataset d = ReadDatasetCsv(out);
  EXPECT_EQ(d.metadata().at("maneuver"), kStarboard);
  EXPECT_EQ(d.rows(), 40);
  EXPECT_NEAR(d["u"](0), 1.2, 1e-12);
  EXPECT_NEAR(d["rev"](0), 613.77, 1e-9);
  EXPECT_EQ(RunUsvid("info --data " + out).exit_code, 0);
}

// A re-import of a log that names no maneuver leaves no stale record file beside the new data.
TEST_F(ImportHsvaCliTest, AReimportWithoutAManeuverRemovesTheRecordFile) {
  const fs::path dir = FreshTempDir();
  const std::string out = (dir / "run.csv").string();
  WriteText(dir / "run.dat", HsvaText(10));
  ASSERT_EQ(
      RunUsvid("import --format hsva-dat --data " + (dir / "run.dat").string() + " --out " + out)
          .exit_code,
      0);
  ASSERT_TRUE(fs::exists(dir / "run.record.json"));
  WriteText(dir / "log.csv", "time,yaw\n0,0\n1,0.1\n2,0.2\n");
  const auto r = RunUsvid("import --format csv --data " + (dir / "log.csv").string() +
                          " --map t=time,psi=yaw --out " + out);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("removed " + (dir / "run.record.json").string()));
  EXPECT_FALSE(fs::exists(dir / "run.record.json"));
  EXPECT_FALSE(ReadDatasetCsv(out).metadata().contains("maneuver"));
}

// A bad log is exit 2 with one line naming file:line, and nothing is written.
TEST_F(ImportHsvaCliTest, ABadLogIsLocatedAndLeavesNothing) {
  const fs::path dir = FreshTempDir();
  std::string text = HsvaText(5);
  text.replace(text.rfind("41.0"), 4, "oops");
  WriteText(dir / "bad.dat", text);
  const std::string out = (dir / "bad.csv").string();
  const auto r =
      RunUsvid("import --format hsva-dat --data " + (dir / "bad.dat").string() + " --out " + out);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr((dir / "bad.dat").string() + ":9:"));
  EXPECT_THAT(r.err, HasSubstr("column 'thrust': 'oops' is not a number"));
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_FALSE(fs::exists(dir / "bad.record.json"));
  const auto map = RunUsvid("import --format hsva-dat --data " + (dir / "bad.dat").string() +
                            " --map t=time --out " + out);
  EXPECT_EQ(map.exit_code, 2);
  EXPECT_THAT(map.err, HasSubstr("--map: applies to --format csv only"));
}

// A record file that is not what usvid writes stops every command reading the data, naming it.
TEST_F(ImportHsvaCliTest, AMalformedRecordFileIsNamed) {
  const fs::path dir = FreshTempDir();
  const std::string data = (dir / "d.csv").string(), record = (dir / "d.record.json").string();
  WriteText(data, "t,u\n0,1\n1,1\n");
  for (const std::string bad : {"{\"maneuver\": ", "{\"maneuver\": 20}"}) {
    WriteText(record, bad);
    const auto r = RunUsvid("info --data " + data);
    EXPECT_EQ(r.exit_code, 2) << bad;
    EXPECT_THAT(r.err, HasSubstr(record)) << bad;
  }
}

struct SharedRun {
  std::string file, maneuver;
};

// The nine shared HSVA zig-zags: each imports with its header's maneuver in F.record.json and
// read back, and --scale 45.7 (the model's scale) takes it to the ship as it does a MARIN log:
// time and speeds x sqrt(45.7), the propeller's revolutions / sqrt(45.7), the record file says
// the scale.
TEST_F(ImportHsvaCliTest, SharedZigZagsImportWithTheirManeuverAndScale) {
  const std::string folder = std::string(USVID_SHARED_DATA_DIR) + "/kvlcc2-hsva";
  if (!fs::exists(folder)) GTEST_SKIP() << "shared data absent: " << folder;
  const std::string deg = "\xC2\xB0";
  const std::vector<SharedRun> runs = {
      {"Z_10_01", "Z10" + deg + "/1" + deg},
      {"Z_10_05", "Z10" + deg + "/5" + deg},
      {"Z_10_10_P", "Z10" + deg + "/10" + deg + " starting to port"},
      {"Z_15_01", "Z15" + deg + "/1" + deg},
      {"Z_15_05", "Z15" + deg + "/5" + deg},
      {"Z_20_05", "Z20" + deg + "/5" + deg},
      {"Z_20_10_S", kStarboard},
      {"Z_25_05", "Z25" + deg + "/5" + deg},
      {"Z_30_05", "Z30" + deg + "/5" + deg}};
  const fs::path dir = FreshTempDir();
  const double root = std::sqrt(45.7);
  for (const SharedRun& run : runs) {
    SCOPED_TRACE(run.file);
    const std::string log = folder + "/HSVA_CPMC_KVLCC2_" + run.file + ".dat";
    const std::string model = (dir / (run.file + ".csv")).string();
    const std::string ship = (dir / (run.file + "_ship.csv")).string();
    const auto r = RunUsvid("import --format hsva-dat --data " + log + " --out " + model);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(ReadJsonFile((dir / (run.file + ".record.json")).string()).at("maneuver"),
              run.maneuver);
    const Dataset m = ReadDatasetCsv(model);
    EXPECT_EQ(m.metadata().at("maneuver"), run.maneuver);
    EXPECT_NEAR(m["u"](0), 1.178, 0.004);

    const auto s =
        RunUsvid("import --format hsva-dat --data " + log + " --scale 45.7 --out " + ship);
    ASSERT_EQ(s.exit_code, 0) << s.err;
    EXPECT_THAT(s.err, HasSubstr("Froude-scaled by lambda = 45.7"));
    const nlohmann::json record = ReadJsonFile((dir / (run.file + "_ship.record.json")).string());
    EXPECT_EQ(record.at("scale"), 45.7);
    EXPECT_EQ(record.at("maneuver"), run.maneuver);
    const Dataset f = ReadDatasetCsv(ship);
    ASSERT_EQ(f.rows(), m.rows());
    EXPECT_NEAR(f.duration(), m.duration() * root, 1e-9 * f.duration());
    EXPECT_NEAR(f.t()(100), m.t()(100) * root, 1e-9);
    EXPECT_NEAR(f["u"](0), m["u"](0) * root, 1e-9);
    EXPECT_NEAR(f["north"](50), m["north"](50) * 45.7, 1e-6);
    EXPECT_NEAR(f["rev"](0), m["rev"](0) / root, 1e-9);
    EXPECT_NEAR(f["r"](100), m["r"](100) / root, 1e-12);
    EXPECT_EQ(f["delta"](100), m["delta"](100));
    EXPECT_EQ(f.metadata().at("maneuver"), run.maneuver);
  }
}

// MARIN's log scales as HSVA's does (its roll phi and roll rate p have their dimensions), and
// names no maneuver, so it leaves no record file.
TEST_F(ImportHsvaCliTest, MarinLogScalesTooAndHasNoRecordFile) {
  const std::string log =
      std::string(USVID_SHARED_DATA_DIR) + "/kvlcc2-marin/MARIN_FREE_KVLCC2_zz_20_m.dat";
  if (!fs::exists(log)) GTEST_SKIP() << "shared data absent: " << log;
  const fs::path dir = FreshTempDir();
  const auto r = RunUsvid("import --format marin-dat --data " + log + " --scale " +
                          std::to_string(1.0 / 45.7) + " --out " + (dir / "zz.csv").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("phi x1 (angle)"));
  const Dataset d = ReadDatasetCsv((dir / "zz.csv").string());
  EXPECT_NEAR(d["u"](0), 8.1 / std::sqrt(45.7), 0.01);  // about the HSVA model's 1.18 m/s
  EXPECT_FALSE(fs::exists(dir / "zz.record.json"));
}

}  // namespace
}  // namespace usvid
