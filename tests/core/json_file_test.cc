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
TEST_F(JsonFileTest, WriteThenReadRoundTrips) {
  const auto path = std::filesystem::temp_directory_path() / "usvid_json_file_test.json";
  const nlohmann::json value = {{"vessel", "odin3dof"}, {"seed", 7}, {"p", {1.5, -2e-9}}};
  WriteJsonFile(path.string(), value);
  EXPECT_EQ(ReadJsonFile(path.string()), value);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace usvid
