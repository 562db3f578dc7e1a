// usvid compare [--suite S.json | --quick] [--threads N] [--baseline PREV/results.json]
//               [--fresh] --out DIR
// The whole benchmark: every method fitted on every training maneuver and scored in free run on
// held-out test maneuvers; writes DIR/results.json, DIR/results.csv and DIR/summary.md. Each
// finished cell is kept in DIR/cells, so the same command resumes a killed run; under
// `mpirun -n N` (built with -DUSVID_WITH_MPI=ON) the cells are spread over the ranks.

#include <chrono>
#include <iostream>
#include <memory>

#include "apps/usvid/commands.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/executable_identity.h"
#include "core/json_file.h"
#include "harness/distributed_run.h"
#include "harness/ranks.h"
#include "harness/regression.h"
#include "harness/report.h"
#include "harness/results.h"
#include "harness/run_suite.h"

namespace usvid {
namespace {

struct CompareOptions {
  std::string suite;
  std::string baseline;
  bool quick = false;
  bool fresh = false;
  int threads = 0;
  std::string out;
};

void RunCompare(const CompareOptions& o) {
  if (!o.suite.empty() && o.quick) throw InputError("compare: give --suite or --quick, not both");
  const Suite suite = o.suite.empty()
                          ? DefaultSuite(o.quick)
                          : ParseSuite(ReadJsonFile(o.suite, JsonComments::kAllowed), o.suite);
  // The baseline is read before hours of fitting, not after.
  const nlohmann::json baseline = o.baseline.empty() ? nlohmann::json() : ReadJsonFile(o.baseline);
  EnsureOutputDirectory(o.out);
  const auto start = std::chrono::steady_clock::now();
  if (ranks::Rank() == 0)
    std::cerr << "usvid compare: suite '" << suite.name << "', " << FitJobs(suite).size()
              << " fits x " << suite.test_maneuvers.size() << " test maneuvers"
              << (ranks::Size() > 1 ? " on " + std::to_string(ranks::Size()) + " ranks" : "")
              << '\n';
  const DistributedRun run = RunSuiteDistributed(
      suite, o.out, {.threads = o.threads, .fresh = o.fresh, .build = ExecutableIdentity()},
      [](const std::string& line) {
        // One write per line: the lines of several MPI ranks must not interleave.
        std::cerr << "usvid compare: " + line + "\n" << std::flush;
      });
  if (ranks::Rank() != 0) return;  // rank 0 writes the outputs
  const std::vector<ResultRow>& rows = run.rows;
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  WriteJsonFile(o.out + "/results.json", ResultsJson(suite, rows, seconds));
  WriteFileAtomically(o.out + "/results.csv", ResultsCsv(rows));
  std::string summary = SummaryMarkdown(suite, rows, seconds);
  int worse = 0;
  if (!o.baseline.empty()) {
    const RegressionReport r = CompareWithBaseline(rows, baseline, o.baseline);
    WriteJsonFile(o.out + "/regressions.json", {{"baseline", o.baseline}, {"groups", r.groups}});
    summary += "\n" + r.Markdown();
    worse = r.worse;
  }
  WriteFileAtomically(o.out + "/summary.md", summary);
  WriteReport(suite, rows, summary, o.out);
  std::cerr << "usvid compare: wrote results.json, results.csv, summary.md, plots and report.html "
               "to "
            << o.out << " (" << seconds << " s)\n";
  if (worse > 0)
    throw RegressionFound("compare: " + std::to_string(worse) + " groups worse than the baseline " +
                          o.baseline + " (see " + o.out + "/regressions.json)");
}

}  // namespace

void AddCompareCommand(CLI::App& app) {
  auto o = std::make_shared<CompareOptions>();
  CLI::App* cmd = app.add_subcommand(
      "compare", "The benchmark: methods x maneuvers x vessels x noise x seeds, held-out scores");
  cmd->add_option("--suite", o->suite, "Suite JSON (default: the embedded default suite)");
  cmd->add_flag("--quick", o->quick, "The default suite, smaller: seconds, not minutes");
  cmd->add_option("--baseline", o->baseline,
                  "A previous results.json: per vessel and method, the cells paired with the "
                  "baseline's and tested (Wilcoxon signed-rank, Holm); exit 3 when any group "
                  "got worse");
  cmd->add_option("--threads", o->threads,
                  "Fits in parallel, per MPI rank (0: OMP_NUM_THREADS, else all cores)");
  cmd->add_flag("--fresh", o->fresh,
                "Run every cell again, discarding the finished cells DIR/cells keeps for resuming");
  cmd->add_option("--out", o->out,
                  "Directory for results.json, results.csv, summary.md, plots, report.html")
      ->required();
  cmd->callback([o] { RunCompare(*o); });
}

}  // namespace usvid
