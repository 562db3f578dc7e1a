#include "harness/external_method.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <thread>

#include "core/csv_dataset.h"
#include "core/error.h"
#include "core/json_file.h"
#include "core/model_view.h"
#include "core/parse_number.h"

extern char** environ;

namespace usvid {
namespace {

namespace fs = std::filesystem;

// A folder of its own under the system's temporary directory, removed when this goes.
class TemporaryFolder {
 public:
  TemporaryFolder() {
    std::string pattern = (fs::temp_directory_path() / "usvid_external_XXXXXX").string();
    if (!mkdtemp(pattern.data()))
      throw InputError("external method: cannot make a temporary folder: " +
                       std::string(std::strerror(errno)));
    path_ = pattern;
  }
  ~TemporaryFolder() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  TemporaryFolder(const TemporaryFolder&) = delete;
  TemporaryFolder& operator=(const TemporaryFolder&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

std::string Join(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ",") + n;
  return out;
}

// The last non-empty line of a file ("" when none), for a failure's message.
std::string LastLine(const fs::path& file) {
  std::ifstream in(file);
  std::string line, last;
  while (std::getline(in, line))
    if (line.find_first_not_of(" \t\r") != std::string::npos) last = line;
  return last;
}

// Runs argv in its own process group with stdout and stderr to files; returns its wait status.
// Past the timeout the group is killed and InputError says so.
int Run(const std::vector<std::string>& argv, const fs::path& out, const fs::path& err,
        double timeout_s, const std::string& what) {
  posix_spawn_file_actions_t files;
  posix_spawn_file_actions_init(&files);
  posix_spawn_file_actions_addopen(&files, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&files, STDOUT_FILENO, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0644);
  posix_spawn_file_actions_addopen(&files, STDERR_FILENO, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0644);
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP);
  posix_spawnattr_setpgroup(&attr, 0);
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = 0;
  const int spawned = posix_spawnp(&pid, args[0], &files, &attr, args.data(), environ);
  posix_spawn_file_actions_destroy(&files);
  posix_spawnattr_destroy(&attr);
  if (spawned != 0)
    throw InputError(what + ": cannot run '" + argv[0] + "': " + std::strerror(spawned));
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  int status = 0;
  while (true) {
    const pid_t done = waitpid(pid, &status, WNOHANG);
    if (done == pid) return status;
    if (done < 0 && errno != EINTR)
      throw InputError(what + ": lost its process: " + std::strerror(errno));
    if (std::chrono::steady_clock::now() > deadline) {
      kill(-pid, SIGKILL);
      while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
      }
      throw InputError(what + ": timed out after " + FormatNumber(timeout_s) + " s (killed)");
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

}  // namespace

ExternalCommand ParseExternalCommand(const nlohmann::json& options, const std::string& where) {
  ExternalCommand c;
  const nlohmann::json name = options.value("name", nlohmann::json());
  if (!name.is_string() || name.get<std::string>().empty())
    throw InputError(where + ": an external method needs \"name\", a non-empty string");
  c.name = name.get<std::string>();
  const nlohmann::json command = options.value("command", nlohmann::json());
  if (!command.is_array() || command.empty())
    throw InputError(where + ": external '" + c.name +
                     "' needs \"command\", a non-empty list of strings");
  for (const auto& part : command) {
    if (!part.is_string() || part.get<std::string>().empty())
      throw InputError(where + ": external '" + c.name + "': command parts are non-empty strings");
    c.command.push_back(part.get<std::string>());
  }
  if (options.contains("timeout_s")) {
    const nlohmann::json& t = options["timeout_s"];
    if (!t.is_number() || !(t.get<double>() > 0) || !std::isfinite(t.get<double>()))
      throw InputError(where + ": external '" + c.name + "': timeout_s must be a positive number");
    c.timeout_s = t.get<double>();
  }
  return c;
}

nlohmann::json IdentifyExternal(const ExternalCommand& command, const Dataset& train,
                                const std::vector<std::string>& states,
                                const std::vector<std::string>& inputs) {
  const std::string what = "external '" + command.name + "'";
  TemporaryFolder folder;
  const fs::path data = folder.path() / "train.csv", model = folder.path() / "model.json";
  const fs::path out = folder.path() / "stdout.txt", err = folder.path() / "stderr.txt";
  WriteDatasetCsv(data.string(), train);
  std::vector<std::string> argv = command.command;
  for (const std::string& a :
       {std::string("--data"), data.string(), std::string("--states"), Join(states),
        std::string("--inputs"), Join(inputs), std::string("--out"), model.string()})
    argv.push_back(a);
  const int status = Run(argv, out, err, command.timeout_s, what);
  const std::string said = LastLine(err);
  const std::string because = said.empty() ? "" : ": " + said;
  if (WIFSIGNALED(status))
    throw InputError(what + ": killed by signal " + std::to_string(WTERMSIG(status)) + because);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw InputError(what + ": exited with code " + std::to_string(WEXITSTATUS(status)) + because);
  if (!fs::exists(model)) throw InputError(what + ": wrote no model.json");
  nlohmann::json m;
  try {
    m = ReadJsonFile(model.string());
  } catch (const InputError& e) {  // file:line:column of the syntax error
    throw InputError(what + ": its model.json is not JSON: " + e.what());
  }
  if (!m.is_object()) throw InputError(what + ": its model.json is not a JSON object");
  if (ModelView(m).EquationStates().empty())
    throw InputError(what + ": its model.json has no \"equations\" (state: expression)");
  // What the command's model leaves out, usvid says (harness/external_method.h).
  const ModelView view(m);
  if (view.Method().empty()) m["method"] = std::string(kExternalMethod) + ":" + command.name;
  if (view.States().empty()) m["states"] = states;
  if (view.Inputs().empty()) m["inputs"] = inputs;
  return m;
}

}  // namespace usvid
