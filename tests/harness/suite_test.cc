// Suites (issue 7): JSON suites are read strictly, the fit jobs skip what a method cannot fit,
// and a run gives one row per fit and test maneuver, each on held-out data, the same at 1 and
// 2 threads, with failures as rows.
#include "harness/suite.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "core/csv_dataset.h"
#include "core/error.h"
#include "harness/results.h"
#include "harness/run_suite.h"
#include "harness/suite_data.h"

namespace usvid {
namespace {

using ::testing::HasSubstr;

class SuiteTest : public ::testing::Test {
 protected:
  static nlohmann::json Small() {
    return {{"name", "small"},
            {"vessels", {"odin3dof", "msd"}},
            {"train_maneuvers", {"random-steps", "zigzag:20/20"}},
            {"test_maneuvers", {"multisine"}},
            {"methods", {"sindy", "fossen-ceres", "eb-lr"}},
            {"noise", {0.005}},
            {"seeds", {1}},
            {"train_seconds", 120},
            {"test_seconds", 60}};
  }
};

// Bad suites name the file and the field at fault.
TEST_F(SuiteTest, BadSuitesAreRefused) {
  auto expect = [](nlohmann::json suite, const std::string& what) {
    try {
      ParseSuite(suite, "s.json");
      FAIL() << what;
    } catch (const InputError& e) {
      EXPECT_THAT(e.what(), HasSubstr("s.json"));
      EXPECT_THAT(e.what(), HasSubstr(what));
    }
  };
  nlohmann::json s = Small();
  s["colour"] = "blue";
  expect(s, "unknown field 'colour'");
  s = Small();
  s.erase("methods");
  expect(s, "missing field 'methods'");
  s = Small();
  s["methods"] = {"magic"};
  expect(s, "unknown method 'magic'");
  // External commands: a name, a command, a positive timeout, and no other method's options.
  auto external = [](nlohmann::json fields) {
    fields["method"] = "external";
    nlohmann::json suite = Small();
    suite["methods"] = nlohmann::json::array({fields});
    return suite;
  };
  expect(external({{"command", {"python3", "m.py"}}}), "needs \"name\"");
  expect(external({{"name", "sindy"}, {"command", {"python3"}}}), "is a usvid method's");
  expect(external({{"name", "mine"}, {"command", nlohmann::json::array()}}), "needs \"command\"");
  expect(external({{"name", "mine"}, {"command", {"python3"}}, {"timeout_s", 0}}),
         "method external: option 'timeout_s' 0 is not allowed: a finite number > 0");
  expect(external({{"name", "mine"}, {"command", {"python3"}}, {"population", 3}}),
         "method external: unknown option 'population' (its options: name, command, timeout_s, "
         "states, inputs)");
  expect(external({{"name", "mine"}, {"command", {"python3"}}, {"rate", 10}}),
         "method external: unknown option 'rate'");
  EXPECT_EQ(ParseSuite(external({{"name", "mine"}, {"command", {"python3", "m.py"}}}), "s.json")
                .methods.at(0)
                .Label(),
            "mine");
  s = Small();
  s["noise"] = {"high"};
  expect(s, "noise");
  s = Small();
  s["seeds"] = nlohmann::json::array();
  expect(s, "seeds");
  s = Small();
  s["train_seconds"] = -5;
  expect(s, "train_seconds");
  // Seeds are whole numbers >= 0: nlohmann would turn these into some uint64_t (fuzzing found
  // 1.9e128, undefined behaviour).
  for (const nlohmann::json& seed : {nlohmann::json(-1), nlohmann::json(1.5),
                                     nlohmann::json::parse("188888888888888888888888888888")}) {
    s = Small();
    s["seeds"] = nlohmann::json::array({seed});  // not {seed}: clang reads that as a copy
    expect(s, "seeds: element " + seed.dump() + " has the wrong type");
  }
  // Method options: known names, each of its kind.
  s = Small();
  s["methods"] = nlohmann::json::array({{{"method", "gp"}, {"populaton", 50}}});
  expect(s, "methods: method gp: unknown option 'populaton' (its options: preset, operators");
  // Each method takes its own options alone (docs/options.md), with the keys all share.
  s = Small();
  s["methods"] = nlohmann::json::array({{{"method", "sindy"}, {"population", 50}}});
  expect(s, "methods: method sindy: unknown option 'population' (its options: threshold, ridge");
  s = Small();
  s["methods"] = nlohmann::json::array({{{"method", "sindy"}, {"threshold", 0.1},
                                         {"library", {"constant", "abs"}},
                                         {"derivative", "sg:21:3"}, {"rate", 10}}});
  EXPECT_NO_THROW(ParseSuite(s, "suite.json"));
  s["methods"][0]["derivative"] = "sg:20";
  expect(s, "method sindy: option 'derivative': ");
  s = Small();
  s["methods"] = nlohmann::json::array({{{"method", "diagnose"}, {"population", 5}}});
  expect(s, "method diagnose: unknown option 'population' (its options: causes, segment_s");
  s = Small();
  s["methods"] = nlohmann::json::array({{{"method", "hybrid"}, {"max_terms", 7}}});
  expect(s, "method hybrid: option 'max_terms' 7 is not allowed: a whole number in [0, 6]");
  for (const auto& [key, value] :
       std::vector<std::pair<std::string, nlohmann::json>>{{"population", 1e300},
                                                           {"population", -3},
                                                           {"generations", 2.5},
                                                           {"operators", 5},
                                                           {"ols_threshold", "small"},
                                                           {"segment_s", -1},
                                                           {"states", {"u", 3}}}) {
    s = Small();
    s["methods"] = nlohmann::json::array({{{"method", "gp"}, {key, value}}});
    expect(s, "option '" + key + "'");
  }
  // "pairs": two methods of the suite's, not the same.
  s = Small();
  s["methods"] = {"sindy", "gp"};
  // (nlohmann reads {{"gp", "eb-lr"}} as an object: the arrays are spelled out.)
  auto pairs = [](const std::string& a, const std::string& b) {
    return nlohmann::json::array({nlohmann::json::array({a, b})});
  };
  s["pairs"] = pairs("gp", "eb-lr");
  expect(s, "pairs: 'eb-lr' is not among the suite's methods");
  s["pairs"] = pairs("gp", "gp");
  expect(s, "pairs: a pair of 'gp' with itself");
  s["pairs"] = nlohmann::json::array({"gp", "sindy"});
  expect(s, "pairs: each pair is two method names");
  s["pairs"] = nlohmann::json{{"gp", "sindy"}};
  expect(s, "pairs: must be a list of pairs of method names");
  s["pairs"] = pairs("gp", "sindy");
  EXPECT_EQ(ParseSuite(s, "s.json").pairs.size(), 1u);
  EXPECT_THROW(ParseSuite(nlohmann::json{{"vessels", {"titanic"}},
                                         {"train_maneuvers", {"prbs"}},
                                         {"test_maneuvers", {"prbs"}},
                                         {"methods", {"sindy"}}},
                          "s.json"),
               InputError);
}

// Every method is tried on every maneuver a vessel can run; the headingless msd runs no
// zig-zag.
TEST_F(SuiteTest, FitJobsCoverEveryMethodOnEveryManeuver) {
  const std::vector<FitJob> jobs = FitJobs(ParseSuite(Small(), "s.json"));
  for (const FitJob& j : jobs) {
    if (j.vessel == "msd") {
      EXPECT_NE(j.train_maneuver, "zigzag:20/20");
    }
  }
  // odin3dof: 2 trains x 3 methods; msd: 1 train x 3 methods.
  EXPECT_EQ(jobs.size(), 9u);
}

// A suite starts its costliest fits first (Method::relative_cost: gp, then fossen-ceres), the
// rest in job order, so that the last fit to finish is a short one.
TEST_F(SuiteTest, SlowestFitsStartFirst) {
  nlohmann::json small = Small();
  small["methods"] = {"sindy", "fossen-ceres", "gp", "eb-lr"};
  const std::vector<FitJob> jobs = FitJobs(ParseSuite(small, "s.json"));
  std::vector<size_t> all(jobs.size());
  for (size_t j = 0; j < all.size(); ++j) all[j] = j;
  const std::vector<size_t> order = SlowestFirst(jobs, all);
  ASSERT_EQ(order.size(), jobs.size());
  std::vector<std::string> methods;
  for (size_t j : order) methods.push_back(jobs[j].method.method);
  const auto first_other = std::find_if(methods.begin(), methods.end(), [](const std::string& m) {
    return m != "gp" && m != "fossen-ceres";
  });
  EXPECT_TRUE(std::all_of(methods.begin(), methods.begin() + 3,
                          [](const std::string& m) { return m == "gp"; }));
  EXPECT_TRUE(std::all_of(methods.begin() + 3, first_other,
                          [](const std::string& m) { return m == "fossen-ceres"; }));
  EXPECT_TRUE(std::none_of(first_other, methods.end(), [](const std::string& m) {
    return m == "gp" || m == "fossen-ceres";
  }));
  // The cheap ones keep their job order.
  std::vector<size_t> rest(order.begin() + (first_other - methods.begin()), order.end());
  EXPECT_TRUE(std::is_sorted(rest.begin(), rest.end()));
  // A small GP search (compare --quick's: 300 x 10 of the default 2000 x 50) is cheap: the
  // shooting fits start before it.
  small["methods"] = {"sindy", {{"method", "gp"}, {"population", 300}, {"generations", 10}},
                      "fossen-ceres"};
  const std::vector<FitJob> quick = FitJobs(ParseSuite(small, "s.json"));
  std::vector<size_t> cells(quick.size());
  for (size_t j = 0; j < cells.size(); ++j) cells[j] = j;
  EXPECT_EQ(quick.at(SlowestFirst(quick, cells).front()).method.method, "fossen-ceres");
  // The searches through a vessel refit it once per proposal (the hybrid's terms, diagnose's
  // effects): on a vessel's logs they are the longest fits, and start before GP and the refit.
  small["methods"] = {"refit", "gp", "diagnose", "hybrid"};
  const std::vector<FitJob> searches = FitJobs(ParseSuite(small, "s.json"));
  std::vector<size_t> all_searches(searches.size());
  for (size_t j = 0; j < all_searches.size(); ++j) all_searches[j] = j;
  std::vector<std::string> started;
  for (size_t j : SlowestFirst(searches, all_searches))
    if (started.empty() || started.back() != searches[j].method.method)
      started.push_back(searches[j].method.method);
  EXPECT_THAT(started, ::testing::ElementsAre("hybrid", "diagnose", "gp", "refit"));
}

// A small suite: one row per fit and test maneuver, each scored on another seed, the same at
// 1 and 2 threads, and no NaN in the outputs.
TEST_F(SuiteTest, RunGivesTheSameRowsAtAnyThreadCount) {
  const Suite suite = ParseSuite(Small(), "s.json");
  const std::vector<ResultRow> one = RunSuite(suite, 1), two = RunSuite(suite, 2);
  ASSERT_EQ(one.size(), 9u);
  for (size_t i = 0; i < one.size(); ++i) {
    nlohmann::json a = one[i].ToJson(), b = two[i].ToJson();
    a.erase("fit_seconds");  // wall time, the one thing that may differ
    b.erase("fit_seconds");
    EXPECT_EQ(a, b) << i;
  }
  int failed = 0;
  for (const ResultRow& r : one) {
    EXPECT_NE(r.test_seed, r.seed);  // held out
    if (r.status != "ok") {
      // What cannot be fitted says why: fossen-ceres off odin3dof, eb-lr without steady states.
      EXPECT_TRUE(r.method == "eb-lr" || (r.method == "fossen-ceres" && r.vessel == "msd"))
          << r.method << " " << r.vessel << " " << r.status;
      ++failed;
      continue;
    }
    EXPECT_TRUE(std::isfinite(r.mean_fit_percent));
    EXPECT_GT(r.terms, 0);
    // Structure recovery where the true terms are known; parameter error where the model names
    // the simulator's parameters (fossen-ceres on odin3dof, trained on random steps: near 0).
    EXPECT_TRUE(r.precision.has_value() && r.recall.has_value()) << r.vessel;
    if (r.method == "fossen-ceres" && r.train_maneuver == "random-steps") {
      ASSERT_TRUE(r.parameter_error.has_value());
      EXPECT_LT(*r.parameter_error, 0.05);
      EXPECT_EQ(*r.recall, 1.0);
    }
  }
  EXPECT_GT(failed, 0);
  EXPECT_EQ(ResultsJson(suite, one, 1.0).dump().find("null"), std::string::npos);
  const std::string md = SummaryMarkdown(suite, one, 1.0);
  EXPECT_THAT(md, HasSubstr("## odin3dof"));
  EXPECT_THAT(md, HasSubstr("Best training maneuver"));
  EXPECT_EQ(ResultsCsv(one).substr(0, 6), "vessel");
}

// The input representation (issue 19): on a vessel that logs its jets, a method that takes its
// inputs as channels is fitted on the waterjet map's forces unless it says "forces": "none", and
// every row says which inputs drove its model; an unknown map is refused.
TEST_F(SuiteTest, RowsSayWhichInputsDroveTheModel) {
  nlohmann::json s = {{"name", "jets"},
                      {"vessels", {"odin-hs"}},
                      {"train_maneuvers", {"random-steps"}},
                      {"test_maneuvers", {"random-steps"}},
                      {"methods", {"sindy", {{"method", "sindy"}, {"forces", "none"}}}},
                      {"train_seconds", 60},
                      {"test_seconds", 30}};
  const std::vector<ResultRow> rows = RunSuite(ParseSuite(s, "s.json"), 1);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].inputs, "forces waterjet: tau_x,tau_y,tau_n,jet_flow") << rows[0].status;
  EXPECT_EQ(rows[1].inputs, "throttle,nozzle,bucket") << rows[1].status;
  EXPECT_EQ(rows[0].ToJson().at("inputs"), rows[0].inputs);
  s["methods"] = {{{"method", "sindy"}, {"forces", "magic"}}};
  EXPECT_THROW(ParseSuite(s, "s.json"), InputError);
}

// results.csv is RFC 4180: a field with a comma (GP's label gp[+,-,*,abs], the inputs) is quoted,
// so every row has as many fields as the header.
TEST_F(SuiteTest, ResultsCsvQuotesFieldsWithCommas) {
  ResultRow row;
  row.vessel = "odin-hs";
  row.method = "gp[+,-,*,abs]";
  row.inputs = "forces waterjet: tau_x,tau_y,tau_n,jet_flow";
  row.status = "failed: \"x\", y";
  const std::string csv = ResultsCsv({row});
  EXPECT_THAT(csv,
              HasSubstr(",\"gp[+,-,*,abs]\",\"forces waterjet: tau_x,tau_y,tau_n,jet_flow\","));
  // Count the fields outside quotes on each line.
  std::vector<int> fields;
  int count = 1;
  bool quoted = false;
  for (char c : csv) {
    if (c == '"') quoted = !quoted;
    if (!quoted && c == ',') ++count;
    if (!quoted && c == '\n') {
      fields.push_back(count);
      count = 1;
    }
  }
  ASSERT_EQ(fields.size(), 2u);
  EXPECT_EQ(fields[0], fields[1]);
}

// A suite on measured files: the entries are read strictly, paths are taken from the suite
// file's folder, and the simulated-suite fields do not apply.
TEST_F(SuiteTest, MeasuredDataSuitesAreReadStrictly) {
  const nlohmann::json ok = {
      {"name", "logs"},
      {"vessels", {"odin3dof"}},
      {"data",
       {{"train", {{{"name", "a"}, {"file", "logs/a.csv"}}}},
        {"test", {{{"name", "b"}, {"file", "/abs/b.dat"}, {"format", "marin-dat"}}}}}},
      {"methods", {"nominal", "refit", "diagnose", "nomoto"}}};
  const Suite suite = ParseSuite(ok, "/studies/s.json");
  ASSERT_TRUE(suite.Measured());
  EXPECT_EQ(suite.train_data.at(0).files, std::vector<std::string>{"/studies/logs/a.csv"});
  EXPECT_EQ(suite.test_data.at(0).files, std::vector<std::string>{"/abs/b.dat"});
  EXPECT_EQ(suite.train_maneuvers, std::vector<std::string>{"a"});
  EXPECT_EQ(suite.noise, std::vector<double>{0.0});
  auto expect = [](nlohmann::json suite, const std::string& what) {
    try {
      ParseSuite(suite, "s.json");
      FAIL() << what;
    } catch (const InputError& e) {
      EXPECT_THAT(e.what(), HasSubstr("s.json"));
      EXPECT_THAT(e.what(), HasSubstr(what));
    }
  };
  nlohmann::json s = ok;
  s["data"]["train"][0]["colour"] = "blue";
  expect(s, "unknown field 'colour'");
  s = ok;
  s["data"]["train"][0]["format"] = "excel";
  expect(s, "format 'excel'");
  s = ok;
  s["data"]["train"][0]["map"] = "t=time";
  expect(s, "csv-log only");
  s = ok;
  s["data"]["train"][0]["from_s"] = 50;
  s["data"]["train"][0]["to_s"] = 10;
  expect(s, "from_s must be before to_s");
  s = ok;
  s["data"]["test"][0].erase("file");
  expect(s, "missing field 'file'");
  s = ok;
  s["train_maneuvers"] = {"prbs"};
  expect(s, "does not apply");
  s = ok;
  s["vessels"] = {"odin3dof", "msd"};
  expect(s, "at most one vessel");
  s = ok;
  s["data"]["train"] = nlohmann::json::array();
  expect(s, "data: train");
  // Several records in one training entry, fitted jointly (core/records.h); a test is one file.
  s = ok;
  s["data"]["train"][0]["file"] = {"logs/a.csv", "/abs/c.csv"};
  EXPECT_EQ(ParseSuite(s, "/studies/s.json").train_data.at(0).files,
            (std::vector<std::string>{"/studies/logs/a.csv", "/abs/c.csv"}));
  s["data"]["train"][0]["file"] = nlohmann::json::array();
  expect(s, "a non-empty list of paths");
  s = ok;
  s["data"]["test"][0]["file"] = {"b.dat", "c.dat"};
  expect(s, "a test entry is one file");
}

// "end_at_stop": each record of an entry ends at its propeller's last running row (the recovery
// after a test, preprocessing/record_end.h), and the entry says so when it is written back.
TEST_F(SuiteTest, AnEntryEndsEachRecordWhereItsPropellerStops) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "usvid_suite_end";
  std::filesystem::create_directories(dir);
  std::ofstream((dir / "run.csv").string()) << "t,n,r\n0,10,0.01\n0.1,10,0.02\n0.2,10,0.03\n"
                                               "0.3,10,0.04\n0.4,0,0.3\n0.5,0,-0.2\n";
  const nlohmann::json entry = {{"name", "run"}, {"file", "run.csv"}, {"end_at_stop", "n"}};
  const SuiteData d = ParseSuiteData(entry, dir.string(), "s.json: data");
  const Dataset data = LoadSuiteData(d);
  ASSERT_EQ(data.rows(), 4);
  EXPECT_DOUBLE_EQ(data["r"](3), 0.04);
  EXPECT_EQ(SuiteDataToJson(d).at("end_at_stop"), "n");
  nlohmann::json bad = entry;
  bad["end_at_stop"] = 1;
  EXPECT_THROW(ParseSuiteData(bad, dir.string(), "s.json: data"), InputError);
  std::filesystem::remove_all(dir);
}

// An HSVA log in a suite: "format": "hsva-dat" reads it as `usvid import` does, keeping its
// header's maneuver; "scale" Froude-scales it as `import --scale` does (time x sqrt(lambda)),
// before from_s and to_s cut it; the entry says so when written back; a scale of 0 or below is
// refused naming the entry. A csv entry's F.record.json gives its maneuver too; a joined list
// of files has none.
TEST_F(SuiteTest, AnHsvaEntryKeepsItsManeuverAndScales) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "usvid_suite_hsva";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::string text = " HSVA\n KVLCC2\n Z20\xB0/10\xB0 starting to starboard\n Title\n";
  for (int k = 0; k < 20; ++k)
    text += std::to_string(0.05 * k) + " " + std::to_string(0.06 * k) +
            " 0 0 1.2 0 0 0.1 -0.03 10.2295 41.0 1.1\n";
  std::ofstream((dir / "z.dat").string(), std::ios::binary) << text;
  const std::string maneuver = "Z20\xC2\xB0/10\xC2\xB0 starting to starboard";
  nlohmann::json entry = {{"name", "z"}, {"file", "z.dat"}, {"format", "hsva-dat"}};
  const Dataset model = LoadSuiteData(ParseSuiteData(entry, dir.string(), "s.json: data"));
  EXPECT_EQ(model.metadata().at("maneuver"), maneuver);
  EXPECT_EQ(model.rows(), 20);
  EXPECT_FALSE(
      SuiteDataToJson(ParseSuiteData(entry, dir.string(), "s.json: data")).contains("scale"));

  entry["scale"] = 4;
  entry["to_s"] = 1.0;  // ship time: the rows of the first 0.5 s of the log
  const SuiteData d = ParseSuiteData(entry, dir.string(), "s.json: data");
  EXPECT_EQ(d.scale, 4.0);
  const Dataset ship = LoadSuiteData(d);
  ASSERT_EQ(ship.rows(), 10);
  EXPECT_NEAR(ship.t()(1), 0.1, 1e-12);
  EXPECT_NEAR(ship["u"](0), 2.4, 1e-12);
  EXPECT_NEAR(ship["rev"](0), 10.2295 * 60 / 2, 1e-9);
  EXPECT_EQ(ship.metadata().at("maneuver"), maneuver);
  const nlohmann::json back = SuiteDataToJson(d);
  EXPECT_EQ(back.at("scale"), 4.0);
  EXPECT_EQ(back.at("format"), "hsva-dat");
  EXPECT_EQ(ParseSuiteData(back, "", "again").scale, 4.0);

  for (const nlohmann::json& bad :
       {nlohmann::json(0), nlohmann::json(-45.7), nlohmann::json("4")}) {
    entry["scale"] = bad;
    try {
      ParseSuiteData(entry, dir.string(), "s.json: data.train[0]");
      ADD_FAILURE() << "accepted scale " << bad;
    } catch (const InputError& e) {
      EXPECT_THAT(e.what(), HasSubstr("s.json: data.train[0]: 'scale'"));
    }
  }

  std::ofstream((dir / "c.csv").string()) << "t,u\n0,1\n0.1,1\n0.2,1\n0.3,1\n";
  std::ofstream((dir / "c.record.json").string()) << R"({"maneuver": "Z10/10"})";
  const nlohmann::json csv = {{"name", "c"}, {"file", "c.csv"}};
  EXPECT_EQ(
      LoadSuiteData(ParseSuiteData(csv, dir.string(), "s.json: data")).metadata().at("maneuver"),
      "Z10/10");
  const nlohmann::json both = {{"name", "c"}, {"file", {"c.csv", "c.csv"}}};
  EXPECT_FALSE(LoadSuiteData(ParseSuiteData(both, dir.string(), "s.json: data"))
                   .metadata()
                   .contains("maneuver"));
  std::filesystem::remove_all(dir);
}

// Trained and tested on files: the nominal vessel fits its own clean data exactly, every method
// gives a row per test file with the heading scored too, only GP runs once per seed, and the
// rows are the same at 1 and 2 threads.
TEST_F(SuiteTest, MeasuredSuiteTrainsAndTestsOnTheFiles) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "usvid_suite_measured_test";
  std::filesystem::create_directories(dir);
  WriteDatasetCsv((dir / "train.csv").string(),
                  SimulateForSuite("odin3dof", "random-steps", 120, 0.0, 1));
  WriteDatasetCsv((dir / "test.csv").string(),
                  SimulateForSuite("odin3dof", "multisine", 60, 0.0, 2));
  const nlohmann::json j = {
      {"name", "files"},
      {"vessels", {"odin3dof"}},
      {"data",
       {{"train", {{{"name", "steps"}, {"file", "train.csv"}}}},
        {"test",
         {{{"name", "sines"}, {"file", "test.csv"}},
          {{"name", "sines, last 30 s"}, {"file", "test.csv"}, {"from_s", 30}}}}}},
      {"methods",
       {"nominal",
        {{"method", "refit"}, {"refit_params", {"Nv"}}},
        "sindy",
        {{"method", "gp"}, {"population", 50}, {"generations", 2}}}},
      {"seeds", {1, 2}}};
  const Suite suite = ParseSuite(j, (dir / "suite.json").string());
  EXPECT_EQ(FitJobs(suite).size(), 5u);  // nominal, refit, sindy once; gp per seed
  const std::vector<ResultRow> one = RunSuite(suite, 1), two = RunSuite(suite, 2);
  ASSERT_EQ(one.size(), 10u);
  for (size_t i = 0; i < one.size(); ++i) {
    ASSERT_EQ(one[i].status, "ok") << one[i].method;
    EXPECT_TRUE(one[i].channel_fit_percent.contains("psi")) << one[i].method;
    nlohmann::json a = one[i].ToJson(), b = two[i].ToJson();
    a.erase("fit_seconds");
    b.erase("fit_seconds");
    EXPECT_EQ(a, b) << i;
    if (one[i].method == "nominal" || one[i].method == "refit") {
      EXPECT_GT(one[i].mean_fit_percent, 99.9) << one[i].method << " " << one[i].test_maneuver;
    }
  }
  EXPECT_THAT(SummaryMarkdown(suite, one, 1.0), HasSubstr("sines: free-run fit % per channel"));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace usvid
