// `usvid compare` as a user runs it (issue 7): every output written, no NaN, a report.html that
// holds its figures inline, and regression tracking against a baseline (exit 3 when worse).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "core/csv_tokenizer.h"
#include "core/json_file.h"
#include "tests/apps/run_usvid.h"

namespace usvid {
namespace {

using testing::FreshTempDir;
using ::testing::HasSubstr;
using testing::RunUsvid;
using testing::WriteText;
namespace fs = std::filesystem;

class CompareCliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = FreshTempDir();
    suite_ = (dir_ / "suite.json").string();
    WriteText(suite_, nlohmann::json{{"name", "cli"},
                                     {"vessels", {"odin3dof", "eb2dof"}},
                                     {"train_maneuvers", {"random-steps", "stepgrid:3/1"}},
                                     {"test_maneuvers", {"multisine", "random-steps"}},
                                     {"methods", {"sindy", "fossen-ceres", "eb-lr"}},
                                     {"noise", {0.005}},
                                     {"seeds", {1, 2}},
                                     {"train_seconds", 120},
                                     {"test_seconds", 60}}
                          .dump());
  }
  fs::path dir_;
  std::string suite_;
};

TEST_F(CompareCliTest, WritesEveryOutputAndAReportWithFigures) {
  const auto out = dir_ / "run";
  const auto r = RunUsvid("compare --suite " + suite_ + " --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* f : {"results.json", "results.csv", "summary.md", "report.html",
                        "fit_odin3dof.svg", "fit_eb2dof.svg"})
    EXPECT_TRUE(fs::exists(out / f)) << f;
  const nlohmann::json results = ReadJsonFile((out / "results.json").string());
  EXPECT_EQ(results.dump().find("null"), std::string::npos);
  for (const auto& row : results.at("rows")) {
    EXPECT_TRUE(row.contains("train_maneuver") && row.contains("test_maneuver") &&
                row.contains("seed"));
    // A combination a method cannot fit is a row that says why, with no numbers.
    const std::string status = row.at("status");
    EXPECT_TRUE(status == "ok" || status.starts_with("failed: ")) << status;
    EXPECT_EQ(row.contains("mean_fit_percent"), status == "ok");
  }
  const std::string html = ReadTextFile((out / "report.html").string());
  long svgs = 0;
  for (size_t at = html.find("<svg"); at != std::string::npos; at = html.find("<svg", at + 1))
    ++svgs;
  EXPECT_GE(svgs, 4);  // a heat map and a run figure per vessel, inline
  EXPECT_EQ(html.find("src=\""), std::string::npos);  // self-contained
  EXPECT_THAT(ReadTextFile((out / "summary.md").string()), HasSubstr("Best training maneuver"));
}

// With more methods than a figure can show legibly, the report's run figure shows nominal and
// the three of best median fit, and every method behind a toggle (an HTML <details>, no script).
TEST_F(CompareCliTest, ManyMethodsShowTheBestThreeAndEveryMethodOnAToggle) {
  const std::string suite = (dir_ / "many.json").string();
  WriteText(suite,
            nlohmann::json{{"name", "many"},
                           {"vessels", {"odin3dof"}},
                           {"train_maneuvers", {"random-steps"}},
                           {"test_maneuvers", {"random-steps"}},
                           {"methods", {"nominal", "sindy", "lti", "fossen-ceres", "nomoto"}},
                           {"noise", {0.005}},
                           {"seeds", {1}},
                           {"train_seconds", 120},
                           {"test_seconds", 60}}
                .dump());
  const auto out = dir_ / "many";
  const auto r = RunUsvid("compare --suite " + suite + " --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string html = ReadTextFile((out / "report.html").string());
  const size_t toggle = html.find("<details><summary>every method (5)</summary>");
  ASSERT_NE(toggle, std::string::npos);
  // The figure before the toggle: four series of models (nominal and three) and the record.
  const size_t figure = html.rfind("<figure", toggle);
  const std::string shown = html.substr(figure, toggle - figure);
  EXPECT_THAT(shown, HasSubstr("nominal"));
  int methods = 0;
  for (const char* m : {"sindy", "lti", "fossen-ceres", "nomoto"})
    methods += shown.find(std::string(m) + " (trained on") != std::string::npos;
  EXPECT_EQ(methods, 3);
}

TEST_F(CompareCliTest, BaselineMarksWhatGotWorse) {
  const auto first = dir_ / "first";
  ASSERT_EQ(RunUsvid("compare --suite " + suite_ + " --out " + first.string()).exit_code, 0);
  // Against itself: no fit worse. The fit times may differ: under a sanitizer, with another
  // test loading the machine, a group can take 1.5 times as long and be marked "slower".
  const auto same =
      RunUsvid("compare --suite " + suite_ + " --baseline " + (first / "results.json").string() +
               " --out " + (dir_ / "same").string());
  EXPECT_TRUE(same.exit_code == 0 || same.exit_code == 3) << same.err;
  const nlohmann::json same_groups = ReadJsonFile((dir_ / "same" / "regressions.json").string());
  for (const auto& g : same_groups.at("groups"))
    EXPECT_NE(g.value("verdict", ""), "worse fit") << g.dump();
  // Against a baseline whose fits were 30 points better: every paired cell dropped by 30, so
  // every group with pairs has median difference -30, each group the Holm-adjusted signed-rank
  // test finds (p_adjusted < 0.05) is "worse fit", at least one is, and the run exits 3.
  nlohmann::json better = ReadJsonFile((first / "results.json").string());
  for (auto& row : better["rows"])
    if (row["status"] == "ok") row["mean_fit_percent"] = row["mean_fit_percent"].get<double>() + 30;
  const std::string better_path = (dir_ / "better.json").string();
  WriteText(better_path, better.dump());
  const auto worse = RunUsvid("compare --suite " + suite_ + " --baseline " + better_path +
                              " --out " + (dir_ / "worse").string());
  EXPECT_EQ(worse.exit_code, 3);
  EXPECT_THAT(worse.err, HasSubstr("worse than the baseline"));
  const nlohmann::json reg = ReadJsonFile((dir_ / "worse" / "regressions.json").string());
  int worse_groups = 0;
  for (const auto& g : reg.at("groups")) {
    if (g.at("pairs").get<int>() == 0) continue;
    EXPECT_NEAR(g.at("median_difference").get<double>(), -30.0, 1e-6) << g.dump();
    EXPECT_GE(g.at("p_adjusted").get<double>(), g.at("p_value").get<double>()) << g.dump();
    if (g.at("p_adjusted").get<double>() < 0.05) {
      EXPECT_EQ(g.at("verdict"), "worse fit") << g.dump();
    }
    worse_groups += g.at("verdict") == "worse fit";
  }
  EXPECT_GT(worse_groups, 0);
  EXPECT_THAT(ReadTextFile((dir_ / "worse" / "summary.md").string()),
              HasSubstr("Wilcoxon signed-rank"));
  // Not a results.json: exit 2.
  const auto bad = RunUsvid("compare --suite " + suite_ + " --baseline " + suite_ + " --out " +
                            (dir_ / "bad").string());
  EXPECT_EQ(bad.exit_code, 2);
}

}  // namespace
}  // namespace usvid

namespace usvid {
namespace {

// Issue 20's row contract: a zig-zag test is re-run closed-loop on every model, and every
// scored row has its prediction horizons; an open-loop test maneuver's rows say that they were
// not replayed. results.csv reads back with Python's csv module: every row as wide as the header.
TEST_F(CompareCliTest, RowsCarryClosedLoopCriteriaAndHorizons) {
  const std::string suite = (dir_ / "zigzag.json").string();
  WriteText(suite, nlohmann::json{{"name", "zigzag"},
                                  {"vessels", {"odin3dof"}},
                                  {"train_maneuvers", {"random-steps"}},
                                  {"test_maneuvers", {"zigzag:20/20", "random-steps"}},
                                  {"methods", {"nominal", "sindy", "eb-lr"}},
                                  {"seeds", {1}},
                                  {"train_seconds", 120},
                                  {"test_seconds", 60}}
                       .dump());
  const auto out = dir_ / "zigzag";
  const auto r = RunUsvid("compare --suite " + suite + " --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json results = ReadJsonFile((out / "results.json").string());
  int replayed = 0;
  for (const auto& row : results.at("rows")) {
    if (row.at("status") != "ok") {  // a failed fit's row still says it was not replayed
      ASSERT_TRUE(row.contains("closed_loop")) << row.dump();
      EXPECT_THAT(row.at("closed_loop").at("status").get<std::string>(), HasSubstr("not replayed"));
      continue;
    }
    EXPECT_TRUE(row.at("horizon_fit_percent").contains("5") &&
                row.at("horizon_fit_percent").contains("30") &&
                row.at("horizon_fit_percent").contains("all"))
        << row.dump();
    const nlohmann::json& c = row.at("closed_loop");
    if (row.at("test_maneuver") == "zigzag:20/20") {
      ASSERT_TRUE(c.contains("first_overshoot_error_deg")) << c.dump();
      replayed += c.at("status") == "ok";
    } else {
      EXPECT_THAT(c.at("status").get<std::string>(), HasSubstr("not replayable"));
    }
  }
  EXPECT_GE(replayed, 2);  // nominal and sindy
  EXPECT_TRUE(results.at("verdict").is_array() && !results.at("verdict").empty());
  const std::string summary = ReadTextFile((out / "summary.md").string());
  EXPECT_LT(summary.find("## Verdict"), summary.find("## odin3dof"));
  if (std::system("python3 -c 'import csv' 2>/dev/null") != 0)
    GTEST_SKIP() << "python3 absent: results.csv not read back";
  const std::string check =
      "python3 -c \"import csv,sys; rows=list(csv.reader(open(sys.argv[1]))); "
      "sys.exit(0 if len(rows) > 1 and all(len(r) == len(rows[0]) for r in rows) else 1)\" " +
      (out / "results.csv").string();
  EXPECT_EQ(std::system(check.c_str()), 0) << "results.csv: rows differ in width from the header";
}

// A suite whose records log the wind and the current (the measured track,
// docs/compare.md#realistic-measured): a method whose equations take any input reads them beside
// the vessel's commands; a vessel model keeps its own inputs.
TEST_F(CompareCliTest, LoggedDisturbancesAreTheEquationMethodsInputs) {
  const auto suite = (dir_ / "logged.json").string();
  WriteText(suite, nlohmann::json{{"name", "logged"},
                                  {"vessels", {"odin3dof"}},
                                  {"train_maneuvers", {"random-steps"}},
                                  {"test_maneuvers", {"random-steps"}},
                                  {"methods", {"lti", "nominal"}},
                                  {"effects", {"current=0.3"}},
                                  {"gusts", "8"},
                                  {"logged", {"wind", "current"}},
                                  {"noise", {0.005}},
                                  {"seeds", {1}},
                                  {"train_seconds", 60},
                                  {"test_seconds", 30}}
                       .dump());
  const auto out = dir_ / "logged";
  const auto r = RunUsvid("compare --suite " + suite + " --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json results = ReadJsonFile((out / "results.json").string());
  int seen = 0;
  for (const auto& row : results.at("rows")) {
    ASSERT_EQ(row.at("status"), "ok") << row.dump();
    const std::string inputs = row.at("inputs");
    if (row.at("method") == "lti") {
      EXPECT_EQ(inputs, "tau_x,tau_y,tau_n,wind_speed,wind_u,wind_v,current_u,current_v");
      ++seen;
    } else {
      EXPECT_EQ(inputs.find("wind"), std::string::npos) << inputs;
    }
  }
  EXPECT_EQ(seen, 1);
  EXPECT_EQ(results.at("suite").at("logged"), nlohmann::json({"wind", "current"}));
}
// A suite naming an unknown maneuver is refused before any fit (exit 2), and writes nothing.
TEST_F(CompareCliTest, AnUnknownManeuverIsRefusedBeforeAnyFit) {
  const std::string suite = (dir_ / "typo.json").string();
  WriteText(suite, nlohmann::json{{"name", "typo"},
                                  {"vessels", {"odin3dof"}},
                                  {"train_maneuvers", {"random-steps"}},
                                  {"test_maneuvers", {"zigzog:20/20"}},
                                  {"methods", {"sindy"}}}
                       .dump());
  const auto out = dir_ / "typo";
  const auto r = RunUsvid("compare --suite " + suite + " --out " + out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("zigzog"));
  EXPECT_THAT(r.err, HasSubstr("test_maneuvers"));
  EXPECT_FALSE(fs::exists(out / "results.json"));
}

}  // namespace
}  // namespace usvid
