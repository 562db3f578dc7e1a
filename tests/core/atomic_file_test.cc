// Results are written whole or not at all.
#include "core/atomic_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/csv_tokenizer.h"
#include "core/error.h"

namespace usvid {
namespace {
namespace fs = std::filesystem;

class AtomicFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("usvid_atomic_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  int FilesIn(const fs::path& d) const {
    return static_cast<int>(std::distance(fs::directory_iterator(d), fs::directory_iterator()));
  }
  fs::path dir_;
};

// A write replaces the old content and leaves no temporary file beside it.
TEST_F(AtomicFileTest, ReplacesContentAndLeavesNoTemporary) {
  const std::string path = (dir_ / "a.csv").string();
  WriteFileAtomically(path, "old\n");
  WriteFileAtomically(path, "new\n");
  EXPECT_EQ(ReadTextFile(path), "new\n");
  EXPECT_EQ(FilesIn(dir_), 1);
}

// A missing directory, a directory as the file, or no permission: an error naming the path,
// and nothing written.
TEST_F(AtomicFileTest, RefusesUnwritablePathsAndWritesNothing) {
  EXPECT_THROW(WriteFileAtomically((dir_ / "no" / "a.csv").string(), "x"), InputError);
  EXPECT_THROW(WriteFileAtomically(dir_.string(), "x"), InputError);
  try {
    WriteFileAtomically((dir_ / "missing" / "a.csv").string(), "x");
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("does not exist"));
  }
  EXPECT_EQ(FilesIn(dir_), 0);
}

// --out DIR is created when missing, refused when it is a file.
TEST_F(AtomicFileTest, OutputDirectoryIsCreatedOrRefused) {
  EnsureOutputDirectory((dir_ / "x" / "y").string());
  EXPECT_TRUE(fs::is_directory(dir_ / "x" / "y"));
  WriteFileAtomically((dir_ / "f").string(), "x");
  EXPECT_THROW(EnsureOutputDirectory((dir_ / "f").string()), InputError);
}

}  // namespace
}  // namespace usvid
