// External methods in `usvid compare` (issue 24): a command outside usvid, called with --data,
// --states, --inputs and --out, is scored like any registered method. One that fails, times out
// or writes no model gives rows saying why, and the rest of the suite is kept.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <regex>

#include "core/json_file.h"
#include "simulators/odin3dof.h"
#include "tests/apps/run_usvid.h"

namespace usvid {
namespace {

using ::testing::HasSubstr;
using testing::FreshTempDir;
using testing::RunUsvid;
using testing::WriteText;
namespace fs = std::filesystem;

// A Python script that checks the arguments the harness passes and writes odin3dof's own
// equations (simulators/odin3dof.h with its default parameters) in channel names.
std::string TrueModelScript() {
  const auto& p = Odin3Dof::kDefaultParams;
  auto n = [&](int i) { return std::to_string(p[i]); };
  using P = Odin3Dof;
  const std::string u = "(tau_x + " + n(P::kM22) + "*v*r - (" + n(P::kXu) + " + " + n(P::kXuu) +
                        "*abs(u))*u) / " + n(P::kM11);
  const std::string v = "(tau_y - " + n(P::kM11) + "*u*r - (" + n(P::kYv) + " + " + n(P::kYvv) +
                        "*abs(v))*v) / " + n(P::kM22);
  const std::string r = "(tau_n - (" + n(P::kM22) + " - " + n(P::kM11) + ")*u*v - " + n(P::kNv) +
                        "*v - (" + n(P::kNr) + " + " + n(P::kNrr) + "*abs(r))*r) / " + n(P::kM33);
  return "import argparse, json\n"
         "a = argparse.ArgumentParser()\n"
         "for k in ('--data', '--states', '--inputs', '--out'): a.add_argument(k, required=True)\n"
         "o = a.parse_args()\n"
         "assert open(o.data).readline().startswith('t,')\n"
         "assert o.states == 'u,v,r' and o.inputs == 'tau_x,tau_y,tau_n', (o.states, o.inputs)\n"
         "json.dump({'method': 'true-odin3dof', 'states': ['u', 'v', 'r'],\n"
         "           'inputs': ['tau_x', 'tau_y', 'tau_n'],\n"
         "           'equations': {'u': '" + u + "', 'v': '" + v + "', 'r': '" + r + "'}},\n"
         "          open(o.out, 'w'))\n";
}

std::map<std::string, std::vector<nlohmann::json>> RowsByMethod(const fs::path& results) {
  std::map<std::string, std::vector<nlohmann::json>> rows;
  const nlohmann::json json = ReadJsonFile(results.string());
  for (const auto& row : json.at("rows"))
    rows[row.at("method").get<std::string>()].push_back(row);
  return rows;
}

TEST(ExternalMethodCliTest, ScoresATrueModelAndKeepsTheSuiteWhenCommandsFail) {
  const fs::path dir = FreshTempDir();
  WriteText(dir / "true_model.py", TrueModelScript());
  WriteText(dir / "fails.py", "import sys\nprint('no convergence here', file=sys.stderr)\n"
                              "sys.exit(1)\n");
  WriteText(dir / "hangs.py", "import time\ntime.sleep(60)\n");
  WriteText(dir / "silent.py", "pass\n");
  // Only the hanging command waits for its timeout; the others get one a loaded machine (the
  // tests run in parallel) cannot reach, so that a slow python3 start is not a failure.
  auto external = [&](const std::string& name, const std::string& script, double timeout_s = 60) {
    return nlohmann::json{{"method", "external"},
                          {"name", name},
                          {"command", {"python3", (dir / script).string()}},
                          {"timeout_s", timeout_s}};
  };
  const fs::path suite = dir / "suite.json";
  WriteText(suite, nlohmann::json{{"name", "external"},
                                  {"vessels", {"odin3dof"}},
                                  {"train_maneuvers", {"random-steps"}},
                                  {"test_maneuvers", {"multisine", "zigzag:20/20"}},
                                  {"methods",
                                   {"nominal", external("mine", "true_model.py"),
                                    external("fails", "fails.py"), external("hangs", "hangs.py", 2),
                                    external("silent", "silent.py")}},
                                  {"noise", {0.005}},
                                  {"seeds", {1}},
                                  {"train_seconds", 120},
                                  {"test_seconds", 90}}
                       .dump());
  const auto r = RunUsvid("compare --suite " + suite.string() + " --threads 2 --out " +
                          (dir / "run").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto rows = RowsByMethod(dir / "run" / "results.json");
  // The true equations score as the simulator itself does (the nominal rows): above 99 % on
  // the held-out multisine, and the same as nominal to 1e-6 on every test.
  ASSERT_EQ(rows["mine"].size(), 2u);
  ASSERT_EQ(rows["nominal"].size(), 2u);
  for (size_t i = 0; i < 2; ++i) {
    const nlohmann::json& mine = rows["mine"][i];
    ASSERT_EQ(mine.at("status"), "ok") << mine.dump();
    ASSERT_EQ(rows["nominal"][i].at("status"), "ok");
    EXPECT_NEAR(mine.at("mean_fit_percent").get<double>(),
                rows["nominal"][i].at("mean_fit_percent").get<double>(), 1e-6);
    if (mine.at("test_maneuver") == "multisine") {
      EXPECT_GE(mine.at("mean_fit_percent").get<double>(), 99.0);
    }
  }
  const std::map<std::string, std::string> why = {
      {"fails", "external 'fails': exited with code 1: no convergence here"},
      {"hangs", "external 'hangs': timed out after 2 s (killed)"},
      {"silent", "external 'silent': wrote no model.json"}};
  for (const auto& [name, message] : why) {
    ASSERT_EQ(rows[name].size(), 2u) << name;
    for (const auto& row : rows[name]) {
      EXPECT_THAT(row.at("status").get<std::string>(), HasSubstr(message));
      EXPECT_FALSE(row.contains("mean_fit_percent"));
    }
  }
  // Failed external fits are not kept as cells: a resumed run tries them again.
  long cells = 0;
  for (const auto& entry : fs::directory_iterator(dir / "run" / "cells"))
    cells += entry.path().filename().string().starts_with("cell-");
  EXPECT_EQ(cells, 2);  // nominal and mine
  // Its temporary folders are gone.
  for (const auto& entry : fs::directory_iterator(fs::temp_directory_path()))
    EXPECT_FALSE(entry.path().filename().string().starts_with("usvid_external_"))
        << entry.path();
}

TEST(ExternalMethodCliTest, ASuiteWithoutACommandIsRefused) {
  const fs::path dir = FreshTempDir();
  const fs::path suite = dir / "suite.json";
  WriteText(suite, nlohmann::json{{"vessels", {"odin3dof"}},
                                  {"train_maneuvers", {"random-steps"}},
                                  {"test_maneuvers", {"multisine"}},
                                  {"methods", {{{"method", "external"}, {"name", "mine"}}}},
                                  {"noise", {0.005}},
                                  {"seeds", {1}}}
                       .dump());
  const auto r = RunUsvid("compare --suite " + suite.string() + " --out " + (dir / "run").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("external 'mine' needs \"command\""));
  EXPECT_FALSE(fs::exists(dir / "run" / "results.json"));
}

}  // namespace
}  // namespace usvid
