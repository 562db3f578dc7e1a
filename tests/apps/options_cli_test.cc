// `usvid methods`: every method with the options it declares, and docs/options.md, which must
// be exactly what `usvid methods --markdown` prints (the page is generated, never hand-edited);
// docs/suites.md likewise, from `usvid compare --fields`.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "core/json_file.h"
#include "tests/apps/run_usvid.h"

namespace usvid {
namespace {

using ::testing::HasSubstr;
using testing::RunUsvid;

TEST(OptionsCliTest, ListsEveryMethodWithItsOptions) {
  const auto r = RunUsvid("methods");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("gp: GP-SR"));
  EXPECT_THAT(r.out, HasSubstr("  max_depth (--max-depth): a whole number in [2, 17]; default 6"));
  EXPECT_THAT(r.out, HasSubstr("  threshold (--threshold): a finite number >= 0; default none"));
  EXPECT_THAT(r.out, HasSubstr("  library (--library): a list of constant, products, abs"));
}

TEST(OptionsCliTest, TheOptionsPageIsTheDeclarations) {
  const auto r = RunUsvid("methods --markdown");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream page(std::string(USVID_SOURCE_DIR) + "/docs/options.md");
  ASSERT_TRUE(page) << "docs/options.md is missing";
  std::stringstream text;
  text << page.rdbuf();
  EXPECT_EQ(text.str(), r.out)
      << "docs/options.md is out of date: ./build/usvid methods --markdown > docs/options.md";
}

// docs/suites.md is generated the same way, from the one declaration of a suite's fields
// (harness/suite_fields.h).
TEST(OptionsCliTest, TheSuitesPageIsTheDeclarations) {
  const auto r = RunUsvid("compare --fields");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream page(std::string(USVID_SOURCE_DIR) + "/docs/suites.md");
  ASSERT_TRUE(page) << "docs/suites.md is missing";
  std::stringstream text;
  text << page.rdbuf();
  EXPECT_EQ(text.str(), r.out)
      << "docs/suites.md is out of date: ./build/usvid compare --fields > docs/suites.md";
}

// The documented example method (docs/adding-a-method.md), lti, declares two options and
// nothing else: they reach the command line and suites by their declaration alone, refused
// there with one line when out of range (Python: tests/python/module_test.py).
TEST(OptionsCliTest, TheExampleMethodsTwoOptionsReachTheCommandLineAndSuites) {
  const auto dir = testing::FreshTempDir();
  const std::string data = (dir / "msd.csv").string(), model = (dir / "model.json").string();
  ASSERT_EQ(RunUsvid("simulate --vessel msd --maneuver random-steps --duration 120 --out " + data)
                .exit_code,
            0);
  auto r = RunUsvid("identify --method lti --vessel msd --data " + data +
                    " --ridge 0.5 --constant no --out " + model);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json m = ReadJsonFile(model);
  EXPECT_EQ(m.at("options"), (nlohmann::json{{"ridge", 0.5}, {"constant", "no"}}));
  EXPECT_FALSE(m.at("parameters").contains("v.1"));  // no constant
  r = RunUsvid("identify --method lti --vessel msd --data " + data + " --ridge -1 --out " + model);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("method lti: option 'ridge' -1.0 is not allowed: a finite number "
                               ">= 0"));
  const auto suite = [&](const nlohmann::json& method) {
    const std::string file = (dir / "suite.json").string();
    testing::WriteText(file, nlohmann::json{{"vessels", {"msd"}},
                                            {"train_maneuvers", {"random-steps"}},
                                            {"test_maneuvers", {"multisine"}},
                                            {"methods", {method}},
                                            {"train_seconds", 60},
                                            {"test_seconds", 30}}
                                 .dump());
    return RunUsvid("compare --suite " + file + " --fresh --out " + (dir / "out").string());
  };
  r = suite({{"method", "lti"}, {"ridge", 0.5}, {"constant", "no"}});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json results = ReadJsonFile((dir / "out" / "results.json").string());
  EXPECT_EQ(results.at("rows").at(0).at("status"), "ok");
  r = suite({{"method", "lti"}, {"constant", "maybe"}});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("method lti: option 'constant' \"maybe\" is not allowed: one of "
                               "yes, no"));
}

}  // namespace
}  // namespace usvid
