// JSON files: syntax errors are located by line and column; writes round-trip.
#include "core/json_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "core/error.h"

namespace usvid {
namespace {

class JsonFileTest : public ::testing::Test {};

// A truncated model file names the line and column where it broke off.
TEST_F(JsonFileTest, SyntaxErrorNamesLineAndColumn) {
  try {
    ParseJson("{\n  \"method\": \"gp\",\n  \"parameters\": {\"a\": 1,\n", "model.json");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::StartsWith("model.json:4:1: invalid JSON"));
  }
  try {
    ParseJson("{\"a\": [1, 2,, 3]}", "m.json");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::StartsWith("m.json:1:13: invalid JSON"));
  }
}

// What is written reads back equal.
// A number JSON allows but a double cannot hold is bad input too, not an internal error (found
// by fuzz/suite_fuzzer).
TEST_F(JsonFileTest, NumberOverflowIsBadInput) {
  try {
    ParseJson(R"({"seeds": [66666e6266]})", "s.json");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::StartsWith("s.json: invalid JSON: number overflow"));
  }
}

// A suite a person writes may explain itself in comments; a model file stays plain JSON.
TEST_F(JsonFileTest, CommentsOnlyWhereAllowed) {
  const std::string text = "// the study\n{\"seeds\": [1, 2] /* two */}\n";
  EXPECT_EQ(ParseJson(text, "s.json", JsonComments::kAllowed), nlohmann::json({{"seeds", {1, 2}}}));
  EXPECT_THROW(ParseJson(text, "model.json"), InputError);
}

TEST_F(JsonFileTest, WriteThenReadRoundTrips) {
  const auto path = std::filesystem::temp_directory_path() / "usvid_json_file_test.json";
  const nlohmann::json value = {{"vessel", "odin3dof"}, {"seed", 7}, {"p", {1.5, -2e-9}}};
  WriteJsonFile(path.string(), value);
  EXPECT_EQ(ReadJsonFile(path.string()), value);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace usvid
