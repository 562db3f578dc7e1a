#include "tests/apps/run_usvid.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <vector>
#include <fstream>
#include <sstream>

namespace usvid::testing {
namespace {

std::string Slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Removes the folders FreshTempDir made for a test once it has passed (a failed test's stay, to
// be looked at).
class TempDirCleaner : public ::testing::EmptyTestEventListener {
 public:
  void Add(const std::filesystem::path& dir) { dirs_.push_back(dir); }
  void OnTestEnd(const ::testing::TestInfo& info) override {
    if (info.result()->Passed())
      for (const auto& dir : dirs_) {
        std::error_code ignored;
        std::filesystem::remove_all(dir, ignored);
      }
    dirs_.clear();
  }

 private:
  std::vector<std::filesystem::path> dirs_;
};

TempDirCleaner& Cleaner() {
  // Owned by gtest's listener list once appended.
  static TempDirCleaner* cleaner = [] {
    auto* c = new TempDirCleaner;
    ::testing::UnitTest::GetInstance()->listeners().Append(c);
    return c;
  }();
  return *cleaner;
}

}  // namespace

std::filesystem::path FreshTempDir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = "usvid_e2e_" + std::string(info->test_suite_name()) + "_" + info->name();
  std::replace(name.begin(), name.end(), '/', '_');
  const auto dir = std::filesystem::temp_directory_path() / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  Cleaner().Add(dir);
  return dir;
}

void WriteText(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

RunResult RunUsvid(const std::string& args) {
  const auto dir = std::filesystem::temp_directory_path();
  const auto out = dir / ("usvid_run_" + std::to_string(::getpid()) + ".out");
  const auto err = dir / ("usvid_run_" + std::to_string(::getpid()) + ".err");
  const std::string cmd =
      std::string(USVID_BINARY) + " " + args + " >" + out.string() + " 2>" + err.string();
  const int status = std::system(cmd.c_str());
  RunResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.out = Slurp(out);
  r.err = Slurp(err);
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return r;
}

int StartUsvid(const std::string& args, const std::filesystem::path& err_file) {
  // exec: the shell becomes usvid, so the pid is usvid's.
  const std::string cmd =
      "exec " + std::string(USVID_BINARY) + " " + args + " >/dev/null 2>" + err_file.string();
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  return pid;
}

int WaitUsvid(int pid) {
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

std::string UsvidBinary() { return USVID_BINARY; }

}  // namespace usvid::testing
