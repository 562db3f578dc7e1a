// usvid: identification of high-speed USV dynamics, and a benchmark of the methods.
// Exit codes: 0 success, 2 bad input or usage (one line naming the file, line or option),
// 3 `compare --baseline` found results worse than the baseline, 1 an internal failure.
// Built with MPI, an error on one of several ranks ends all of them with its exit code.

#include <glog/logging.h>
#include <malloc.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <iostream>

#include "apps/usvid/commands.h"
#include "core/error.h"
#include "harness/ranks.h"
#include "simulation/vessel_simulator.h"

#ifndef USVID_VERSION
#define USVID_VERSION "unknown"
#endif

namespace {

int Run(int argc, char** argv) {
  CLI::App app{
      "usvid: identify the dynamics of high-speed unmanned surface vessels from data, and "
      "measure how well each identification method does."};
  app.set_version_flag("--version", "usvid " USVID_VERSION);
  app.require_subcommand(1);
  usvid::AddImportCommand(app);
  usvid::AddInfoCommand(app);
  usvid::AddSimulateCommand(app);
  usvid::AddVesselCommand(app);
  usvid::AddPreprocessCommand(app);
  usvid::AddActuatorsCommand(app);
  usvid::AddIdentifyCommand(app);
  usvid::AddMethodsCommand(app);
  usvid::AddEvaluateCommand(app);
  usvid::AddCompareCommand(app);
  usvid::AddDiagnoseCommand(app);
  usvid::AddDesignCommand(app);
  usvid::AddInitTrackCommand(app);
  if (argc > 1 && argv[1][0] != '-') {
    const auto subcommands = app.get_subcommands({});
    if (std::none_of(subcommands.begin(), subcommands.end(),
                     [&](const CLI::App* c) { return c->check_name(argv[1]); })) {
      std::cerr << "usvid: error: unknown command '" << argv[1] << "' (see usvid --help)\n";
      return 2;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(e);
    std::cerr << "usvid: error: " << e.what() << " (see usvid --help)\n";
    return 2;
  } catch (const usvid::InputError& e) {
    std::cerr << "usvid: error: " << e.what() << '\n';
    return 2;
  } catch (const usvid::RegressionFound& e) {
    std::cerr << "usvid: " << e.what() << '\n';
    return 3;
  } catch (const std::exception& e) {
    std::cerr << "usvid: internal error: " << e.what() << '\n';
    return 1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  // Blocks of 1 MiB and more are mapped and unmapped on their own. glibc otherwise raises this
  // threshold after the first large block is freed, and a long log's freed columns and Jacobians
  // then stay in the heap: diagnose on a 2-hour log peaked at 272 MB of RSS, 220 MB with this.
  mallopt(M_MMAP_THRESHOLD, 1 << 20);
  // And up to 16 MiB of free memory at the heap's top stays with the process. Fixing the mmap
  // threshold also fixes this at 128 KiB, and a Ceres fit whose residual blocks allocate and free
  // Jets by the megabyte then gave pages back and faulted them in anew at every evaluation:
  // fossen-ceres on odin-hs (Jets of 66) spent 1.1 of its 7.1 s in the kernel, 0.06 s with this
  // (docs/performance.md).
  mallopt(M_TRIM_THRESHOLD, 16 << 20);
  // Ceres logs a solve that cannot start (a candidate model whose first evaluation is not
  // finite, which GP's refits meet and discard) at glog's ERROR level, whatever the solver's
  // logging_type. usvid reports a failed fit itself, on one line: glog prints only fatal errors.
  FLAGS_logtostderr = true;
  FLAGS_minloglevel = google::GLOG_FATAL;
  // A vessel file's notes (its estimated coefficients, its warnings) are the command line's to say.
  usvid::SetVesselNoteSink([](const std::string& note) { std::cerr << note << '\n'; });
  usvid::RanksSession session(argc, argv);
  const int code = Run(argc, argv);
  // One rank's failure must not leave the others waiting for it in a collective.
  if (code != 0 && usvid::ranks::Size() > 1) usvid::ranks::Abort(code);
  return code;
}
