// Runs the built `usvid` binary as a user would, capturing exit code, stdout and stderr.
#pragma once

#include <filesystem>
#include <string>

namespace usvid::testing {

struct RunResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

// `args` is appended to the binary's path as it is (shell quoting is the caller's).
RunResult RunUsvid(const std::string& args);

// A fresh empty directory under the system temp dir, named after the running test.
std::filesystem::path FreshTempDir();

void WriteText(const std::filesystem::path& path, const std::string& text);

}  // namespace usvid::testing
