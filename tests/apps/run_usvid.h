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

// Starts `usvid args` without waiting, stderr to `err_file`; returns its process id (the usvid
// process itself, for kill(2)). Reap it with WaitUsvid, which returns its exit code.
int StartUsvid(const std::string& args, const std::filesystem::path& err_file);
int WaitUsvid(int pid);

// The built binary's path (for commands that wrap it, such as mpirun).
std::string UsvidBinary();

// A fresh empty directory under the system temp dir, named after the running test; removed when
// the test passes, kept when it fails.
std::filesystem::path FreshTempDir();

void WriteText(const std::filesystem::path& path, const std::string& text);

}  // namespace usvid::testing
