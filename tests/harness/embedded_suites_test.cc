// The embedded suites' table (harness/embedded_suites.h): every row reads a file the build
// embedded, every suite file of harness/suites/ is embedded by its path, and --help names every
// row, so that adding a suite is a file and a row, nothing else.
#include "harness/embedded_suites.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace usvid {
namespace {

namespace fs = std::filesystem;

std::string Read(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Each file of the source tree's suite, track and vessel folders is embedded under its path in
// the repository, byte for byte.
TEST(EmbeddedSuitesTest, EveryFileOfTheEmbeddedFoldersIsEmbeddedByItsPath) {
  const fs::path root = USVID_SOURCE_DIR;
  size_t files = 0;
  for (const char* folder : {"harness/suites", "harness/tracks", "docs/vessels/files"})
    for (const fs::directory_entry& e : fs::directory_iterator(root / folder)) {
      const std::string path = fs::relative(e.path(), root).generic_string();
      EXPECT_EQ(EmbeddedText(path), Read(e.path())) << path;
      ++files;
    }
  EXPECT_GE(files, 10u);
  EXPECT_THROW(EmbeddedText("harness/suites/none.json"), std::logic_error);
}

// A simulated row parses, at full size and with --quick, and its suite carries its row's name
// (the quick suite's JSON names itself default-quick).
TEST(EmbeddedSuitesTest, EverySimulatedRowParsesAsItsName) {
  for (const EmbeddedSuite& row : EmbeddedSuites()) {
    if (row.file.empty()) {
      EXPECT_THROW(LoadEmbeddedSuite(row), std::logic_error) << row.name;
      continue;
    }
    const Suite full = LoadEmbeddedSuite(row);
    const Suite quick = LoadEmbeddedSuite(row, /*quick=*/true);
    EXPECT_EQ(full.name, row.name == "quick" ? "default-quick" : std::string(row.name));
    EXPECT_FALSE(quick.methods.empty()) << row.name;
  }
  EXPECT_EQ(LoadEmbeddedSuite("default", true).name, "default-quick");
  EXPECT_EQ(FindEmbeddedSuite("none"), nullptr);
  EXPECT_THROW(LoadEmbeddedSuite("none"), std::logic_error);
}

TEST(EmbeddedSuitesTest, TheHelpAndTheNamesListEveryRow) {
  for (const EmbeddedSuite& row : EmbeddedSuites()) {
    EXPECT_THAT(EmbeddedSuitesHelp(), testing::HasSubstr(std::string(row.name) + " ("));
    EXPECT_THAT(EmbeddedSuiteNames(), testing::HasSubstr(std::string(row.name)));
    EXPECT_TRUE(IsSuiteName(std::string(row.name)));
  }
  EXPECT_FALSE(IsSuiteName("suites/mine.json"));
}

}  // namespace
}  // namespace usvid
