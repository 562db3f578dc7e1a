// A suite's fields, declared once (harness/suite_fields.h): reading and writing walk the same
// list, so every embedded suite written back and read again is the same suite, a field given to
// the other kind of suite is refused naming it, and docs/suites.md is the list
// (tests/apps/options_cli_test.cc checks the page against `usvid compare --fields`).
#include "harness/suite_fields.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "core/error.h"
#include "harness/embedded_suites.h"
#include "harness/suite.h"

namespace usvid {
namespace {

using ::testing::HasSubstr;

// A simulated suite that gives its required fields alone.
nlohmann::json MinimalSimulatedSuite() {
  return {{"vessels", {"odin3dof"}},
          {"train_maneuvers", {"random-steps"}},
          {"test_maneuvers", {"zigzag:20/20"}},
          {"methods", {"nominal"}}};
}

std::string Refusal(const nlohmann::json& suite) {
  try {
    ParseSuite(suite, "s.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// Every simulated embedded suite, written back through the fields and read again, writes the
// same JSON: no field is lost or added on the way (a suite's cells resume by this echo).
TEST(SuiteFieldsTest, EveryEmbeddedSuiteRoundTrips) {
  int suites = 0;
  for (const EmbeddedSuite& row : EmbeddedSuites()) {
    if (row.file.empty()) continue;  // the real suite: made from a data folder
    const Suite suite = LoadEmbeddedSuite(row);
    const nlohmann::json echo = SuiteToJson(suite);
    EXPECT_EQ(SuiteToJson(ParseSuite(echo, "echo.json")), echo) << row.name;
    for (const auto& [key, _] : echo.items())
      EXPECT_TRUE(
          std::ranges::any_of(SuiteFields(), [&](const SuiteField& f) { return f.key == key; }))
          << row.name << ": " << key;
    ++suites;
  }
  EXPECT_GE(suites, 4);
}

// The keys are unique, each field can be read and written, and the ones a kind requires apply
// to it.
TEST(SuiteFieldsTest, EachFieldIsDeclaredOnce) {
  std::set<std::string_view> keys;
  for (const SuiteField& f : SuiteFields()) {
    EXPECT_TRUE(keys.insert(f.key).second) << f.key;
    EXPECT_NE(f.read, nullptr) << f.key;
    EXPECT_NE(f.write, nullptr) << f.key;
    EXPECT_FALSE(f.what.empty()) << f.key;
    for (const bool measured : {false, true}) {
      if (f.RequiredIn(measured)) {
        EXPECT_TRUE(f.AppliesTo(measured)) << f.key;
      }
    }
    // A field of one kind says why when given to the other ("data" makes a suite measured).
    if (f.applies != SuiteKind::kAny && f.key != "data") {
      EXPECT_FALSE(f.elsewhere.empty()) << f.key;
    }
  }
}

// A field of a simulated suite given to one on measured data (and the reverse) is refused,
// naming the file and the field; so is a missing required field.
TEST(SuiteFieldsTest, AFieldOfTheOtherKindIsRefused) {
  const nlohmann::json simulated = MinimalSimulatedSuite();
  EXPECT_EQ(Refusal(simulated), "");
  nlohmann::json cv = simulated;
  cv["cv"] = "runs";
  EXPECT_THAT(Refusal(cv), HasSubstr("s.json: cv: a simulated suite has no runs to leave out"));
  const nlohmann::json measured = {
      {"data",
       {{"train", {{{"name", "a"}, {"file", "a.csv"}}}}, {"test", nlohmann::json::array()}}},
      {"methods", {"nominal"}},
      {"waves", "0.3"}};
  EXPECT_EQ(Refusal(measured),
            "s.json: 'waves' makes simulated records; measured data have their own");
  nlohmann::json seconds = measured;
  seconds.erase("waves");
  seconds["train_seconds"] = 60;
  EXPECT_EQ(Refusal(seconds), "s.json: 'train_seconds' does not apply to a suite on measured data");
  nlohmann::json missing = simulated;
  missing.erase("test_maneuvers");
  EXPECT_EQ(Refusal(missing), "s.json: missing field 'test_maneuvers'");
}

// Defaults come from the declarations' kind: noise 0.5 % simulated, none on measured data.
TEST(SuiteFieldsTest, DefaultsAreThoseDeclared) {
  const Suite s = ParseSuite(MinimalSimulatedSuite(), "s.json");
  EXPECT_EQ(s.name, "suite");
  EXPECT_EQ(s.noise, std::vector<double>{0.005});
  EXPECT_EQ(s.seeds, std::vector<uint64_t>{1});
  EXPECT_EQ(s.train_seconds, 300.0);
  EXPECT_EQ(s.test_seconds, 180.0);
  EXPECT_THAT(SuiteFieldsMarkdown(),
              HasSubstr("| `noise` | every | [0.005] simulated, [0] measured |"));
}

// A field's default as docs/suites.md states it (its declared text) is the value the code gives
// a suite that leaves the field out: the text's first word, read as JSON, is what the field's
// writer writes back, and a field written back as nothing says "none".
TEST(SuiteFieldsTest, EachDeclaredDefaultIsTheCodesDefault) {
  const Suite s = ParseSuite(MinimalSimulatedSuite(), "s.json");
  int checked = 0;
  for (const SuiteField& f : SuiteFields()) {
    if (!f.AppliesTo(/*measured=*/false) || f.RequiredIn(/*measured=*/false)) continue;
    const std::string text(f.default_text);
    const nlohmann::json written = f.write(s);
    if (written.is_null()) {
      EXPECT_TRUE(text.starts_with("none")) << f.key << ": \"" << text << "\"";
    } else {
      const nlohmann::json declared =
          nlohmann::json::parse(text.substr(0, text.find(' ')), nullptr, false);
      EXPECT_EQ(declared, written) << f.key << ": \"" << text << "\"";
    }
    ++checked;
  }
  EXPECT_GE(checked, 10);  // name, pairs, noise, seeds, the conditions, the seconds
}

}  // namespace
}  // namespace usvid
