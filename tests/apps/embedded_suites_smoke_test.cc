// Every embedded suite, seconds-long (`usvid compare --suite NAME --quick`, harness/smoke_suite.h),
// as CI runs them (issue 69): the realistic suite's simulated zig-zags under wind, current, waves
// and saturation, the same with the disturbances logged, and the real suite's five tracks on the
// shared logs (and its sixth, KVLCC2 of both tanks, where a further run is there to score it). No
// row may be refused by the harness's own checks: every model fitted is scored, free run and closed
// loop (a record read as another maneuver than it holds, or a side check that fails, fails the
// scoring of a fitted model). A fit a method itself gives up on (SINDy's "every term of r' was cut"
// on a noisy autopilot record) is the method's row, not the harness's. Before the fix of the
// saturation probe (simulation/typed_vessel_simulator.h), 116 of the realistic suite's 384 rows
// failed so.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/csv_tokenizer.h"
#include "core/json_file.h"
#include "harness/embedded_suites.h"
#include "tests/apps/run_usvid.h"

namespace usvid {
namespace {

using testing::FreshTempDir;
using testing::RunUsvid;
namespace fs = std::filesystem;

// The rows of every results.json under `out` that a harness check refused, one line each.
std::vector<std::string> RefusedRows(const fs::path& out, int& rows) {
  std::vector<std::string> refused;
  for (const auto& e : fs::recursive_directory_iterator(out)) {
    if (e.path().filename() != "results.json") continue;
    const nlohmann::json results = ReadJsonFile(e.path().string());
    for (const nlohmann::json& row : results.at("rows")) {
      ++rows;
      const std::string status = row.at("status").get<std::string>();
      const std::string replay = row.contains("closed_loop")
                                     ? row["closed_loop"].value("status", std::string("ok"))
                                     : std::string("ok");
      const bool fitted = !replay.starts_with("not replayed: the fit failed");
      if (fitted && (status != "ok" || replay.starts_with("not replayed")))
        refused.push_back(
            e.path().parent_path().filename().string() + " " + row.at("method").get<std::string>() +
            " on " + row.at("test_maneuver").get<std::string>() + ": " + status + " / " + replay);
    }
  }
  return refused;
}

// The output folder (`root`/out; the test's fresh temporary folder by default), for more checks.
fs::path ExpectNoRowRefused(const std::string& args, const fs::path& root = {}) {
  const fs::path out = (root.empty() ? FreshTempDir() : root) / "out";
  const auto r = RunUsvid("compare " + args + " --threads 2 --out " + out.string());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  int rows = 0;
  const std::vector<std::string> refused = RefusedRows(out, rows);
  EXPECT_GT(rows, 0) << args;
  EXPECT_THAT(refused, ::testing::IsEmpty()) << args << ": " << refused.size() << " of " << rows;
  return out;
}

TEST(EmbeddedSuitesSmokeTest, RealisticScoresEveryRow) {
  ExpectNoRowRefused("--suite realistic --quick");
}

TEST(EmbeddedSuitesSmokeTest, RealisticMeasuredScoresEveryRow) {
  ExpectNoRowRefused("--suite realistic-measured --quick");
}

// Every other row of the embedded suites' table (harness/embedded_suites.h) runs here, so that a
// suite added as a file and a row runs in CI with nothing more.
TEST(EmbeddedSuitesSmokeTest, EveryOtherSimulatedSuiteScoresEveryRow) {
  const std::set<std::string_view> own_tests = {"default", "quick", "realistic",
                                                "realistic-measured", "real"};
  for (const EmbeddedSuite& suite : EmbeddedSuites())
    if (!own_tests.contains(suite.name))
      ExpectNoRowRefused("--suite " + std::string(suite.name) + " --quick");
}

TEST(EmbeddedSuitesSmokeTest, RealScoresEveryRowOfEveryTrack) {
  const std::string data = USVID_SHARED_DATA_DIR;
  if (!fs::exists(data + "/kvlcc2-hsva")) GTEST_SKIP() << "shared data absent: " << data;
  const fs::path out = ExpectNoRowRefused("--suite real --quick --data-dir " + data);
  // The vessel is named by its file's name: (esso-osaka), not the path of the copy the suite
  // reads; and a further run by its file's stem, not "held-out held-out ..." in the report.
  const std::string summary = ReadTextFile((out / "esso-osaka" / "summary.md").string());
  EXPECT_THAT(summary, ::testing::HasSubstr("### esso-osaka, trained on"));
  EXPECT_THAT(summary, ::testing::HasSubstr("\n## esso-osaka\n"));
  EXPECT_THAT(summary, ::testing::Not(::testing::HasSubstr("vessels/esso-osaka.yaml")));
  const std::string report = ReadTextFile((out / "esso-osaka" / "report.html").string());
  EXPECT_THAT(report, ::testing::Not(::testing::HasSubstr("held-out held-out")));
  EXPECT_THAT(report, ::testing::Not(::testing::HasSubstr("vessels/esso-osaka.yaml")));
  // A plan view of each held-out turning circle and zig-zag (harness/plan_view.h): KVLCC2's
  // tc_35 with its advance and tactical diameter marked, zz_-20 with heading and rudder beside.
  const fs::path kvlcc2 = out / "kvlcc2";
  const std::string circle = ReadTextFile((kvlcc2 / "plan_kvlcc2_2.svg").string());
  for (const char* text : {"plan from the execute", "east [m]", "north [m]", "measured",
                           "turned 90 deg: the advance", "turned 180 deg: the tactical diameter"})
    EXPECT_THAT(circle, ::testing::HasSubstr(text));
  const std::string zigzag = ReadTextFile((kvlcc2 / "plan_kvlcc2_1_heading.svg").string());
  for (const char* text : {"heading turned [deg]", "delta [deg]", "base course +-20"})
    EXPECT_THAT(zigzag, ::testing::HasSubstr(text));
  EXPECT_THAT(ReadTextFile((kvlcc2 / "report.html").string()),
              ::testing::HasSubstr("turned 180 deg: the tactical diameter"));
  // The figures draw the free runs and closed-loop replays the rows were scored on
  // (ResultRow::free_run, replay); resumed, the rows are read back from the cells without them
  // and the report runs the models again: the same figures, to the byte.
  const std::vector<fs::path> figures = {kvlcc2 / "plan_kvlcc2_1_heading.svg",
                                         kvlcc2 / "plan_kvlcc2_2.svg", kvlcc2 / "run_kvlcc2.svg"};
  std::vector<std::string> scored;
  for (const fs::path& f : figures) scored.push_back(ReadTextFile(f.string()));
  const auto resumed = RunUsvid("compare --suite real --quick --data-dir " + data +
                                " --threads 2 --out " + out.string());
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_THAT(resumed.err, ::testing::HasSubstr("resuming:"));
  for (size_t i = 0; i < figures.size(); ++i)
    EXPECT_EQ(ReadTextFile(figures[i].string()), scored[i]) << figures[i];
}

// KVLCC2 of both tanks (docs/compare.md#kvlcc2-both-tanks) runs where a further run can score
// it: a data folder of both tanks' shared runs and one held-out HSVA zig-zag (a copy, named as a
// paper's test might be). The model of all twelve shared runs is scored on it, closed loop too.
TEST(EmbeddedSuitesSmokeTest, RealBothTanksScoreAFurtherRun) {
  const fs::path shared = USVID_SHARED_DATA_DIR;
  if (!fs::exists(shared / "kvlcc2-hsva")) GTEST_SKIP() << "shared data absent: " << shared;
  const fs::path root = FreshTempDir();
  const fs::path data = root / "data";
  for (const char* tank : {"kvlcc2-marin", "kvlcc2-hsva"}) {
    fs::create_directories(data / tank);
    for (const auto& e : fs::directory_iterator(shared / tank))
      fs::create_symlink(fs::absolute(e.path()), data / tank / e.path().filename());
  }
  fs::create_symlink(fs::absolute(shared / "kvlcc2-hsva/HSVA_CPMC_KVLCC2_Z_15_05.dat"),
                     data / "kvlcc2-hsva/held_out_15_05.dat");
  const fs::path out = ExpectNoRowRefused("--suite real --quick --data-dir " + data.string(), root);
  const nlohmann::json results =
      ReadJsonFile((out / "kvlcc2-both-tanks" / "results.json").string());
  ASSERT_FALSE(results.at("rows").empty());
  for (const nlohmann::json& row : results.at("rows")) {
    EXPECT_EQ(row.at("test_maneuver"), "HSVA held_out_15_05");  // named with its tank
    EXPECT_EQ(row.at("closed_loop").at("maneuver"), "zigzag:15/5");
  }
}

}  // namespace
}  // namespace usvid
