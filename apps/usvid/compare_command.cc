// usvid compare [--suite S.json | --suite NAME | --quick] [--data-dir DIR] [--cv runs]
//               [--threads N] [--baseline PREV/results.json] [--fresh] --out DIR
// The whole benchmark: every method fitted on every training maneuver and scored in free run on
// held-out test maneuvers; writes DIR/results.json, DIR/results.csv and DIR/summary.md. Each
// finished cell is kept in DIR/cells, so the same command resumes a killed run; under
// `mpirun -n N` (built with -DUSVID_WITH_MPI=ON) the cells are spread over the ranks.
// `--suite real` runs one such suite per vessel of the measured data in --data-dir
// (harness/real_suite.h), each into DIR/<track>, and DIR/summary.md gathers them. `--cv runs`
// cross-validates a suite on measured data over its runs, leaving each out in turn
// (harness/cross_validation.h).

#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>

#include "apps/usvid/commands.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/executable_identity.h"
#include "core/json_file.h"
#include "harness/cross_validation.h"
#include "harness/distributed_run.h"
#include "harness/embedded_suites.h"
#include "harness/ranks.h"
#include "harness/real_suite.h"
#include "harness/regression.h"
#include "harness/report.h"
#include "harness/results.h"
#include "harness/run_suite.h"
#include "harness/smoke_suite.h"
#include "harness/suite_fields.h"

namespace usvid {
namespace {

struct CompareOptions {
  std::string suite;
  std::string baseline;
  std::string data_dir = "../shared/data";
  std::string cv;  // "" or kCrossValidationRuns
  bool quick = false;
  bool fresh = false;
  int threads = 0;
  std::string out;
};

struct SuiteOutcome {
  std::string summary;
  int worse = 0;  // groups worse than the baseline
};

// One suite fitted and scored into `out`: results.json, results.csv, summary.md, plots and
// report.html (and regressions.json against a baseline).
SuiteOutcome RunSuiteInto(const Suite& suite, const std::string& out, const CompareOptions& o,
                          const nlohmann::json& baseline) {
  EnsureOutputDirectory(out);
  const auto start = std::chrono::steady_clock::now();
  if (ranks::Rank() == 0)
    std::cerr << "usvid compare: suite '" << suite.name << "', " << FitJobs(suite).size()
              << " fits x "
              << (suite.cv.On() ? "the run each leaves out, of " +
                                      std::to_string(suite.test_maneuvers.size()) + " runs"
                                : std::to_string(suite.test_maneuvers.size()) + " test maneuvers")
              << (ranks::Size() > 1 ? " on " + std::to_string(ranks::Size()) + " ranks" : "")
              << '\n';
  const DistributedRun run = RunSuiteDistributed(
      suite, out, {.threads = o.threads, .fresh = o.fresh, .build = ExecutableIdentity()},
      [](const std::string& line) {
        // One write per line: the lines of several MPI ranks must not interleave.
        std::cerr << "usvid compare: " + line + "\n" << std::flush;
      });
  SuiteOutcome outcome;
  if (ranks::Rank() != 0) return outcome;  // rank 0 writes the outputs
  const std::vector<ResultRow>& rows = run.rows;
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  WriteJsonFile(out + "/results.json", ResultsJson(suite, rows, seconds));
  WriteFileAtomically(out + "/results.csv", ResultsCsv(rows));
  outcome.summary = SummaryMarkdown(suite, rows, seconds);
  if (!o.baseline.empty()) {
    const RegressionReport r = CompareWithBaseline(rows, baseline, o.baseline);
    WriteJsonFile(out + "/regressions.json", {{"baseline", o.baseline}, {"groups", r.groups}});
    outcome.summary += "\n" + r.Markdown();
    outcome.worse = r.worse;
  }
  WriteFileAtomically(out + "/summary.md", outcome.summary);
  WriteReport(suite, rows, outcome.summary, out);
  std::cerr << "usvid compare: wrote results.json, results.csv, summary.md, plots and report.html "
               "to "
            << out << " (" << seconds << " s)\n";
  return outcome;
}

// The markdown of a track's summary one heading level down, under the real suite's own title
// (its own title line left out: the track's heading stands for it).
std::string Demoted(const std::string& markdown) {
  std::string out;
  size_t at = 0;
  while (at < markdown.size()) {
    size_t end = markdown.find('\n', at);
    if (end == std::string::npos) end = markdown.size();
    const std::string line = markdown.substr(at, end - at);
    if (!line.starts_with("# ")) out += (line.starts_with("#") ? "#" : "") + line + "\n";
    at = end + 1;
  }
  return out;
}

// --suite real: one suite per vessel of the data folder, each into OUT/<track>.
void RunRealSuite(const CompareOptions& o) {
  if (!o.baseline.empty())
    throw InputError(
        "compare: --baseline compares one suite; give it with a track's own suite "
        "(--suite real runs several)");
  if (!std::filesystem::is_directory(o.data_dir)) {
    std::cerr << "usvid compare: suite 'real' skipped: no data folder " << o.data_dir
              << " (give it with --data-dir; docs/compare.md#the-real-suite)\n";
    return;
  }
  const std::vector<SuiteTrack> tracks = RealSuiteTracks(o.data_dir, o.out + "/vessels", o.cv);
  std::string summary = "# usvid compare: real\n\nMeasured data from " + o.data_dir +
                        ", one track per vessel, each with its own verdict and its own folder "
                        "(results.json, report.html).\n\n";
  for (const SuiteTrack& track : tracks) {
    for (const std::string& note : track.notes)
      std::cerr << "usvid compare: track " << track.name << ": " << note << '\n';
    const SuiteOutcome outcome = RunSuiteInto(o.quick ? SmokeVariant(track.suite) : track.suite,
                                              o.out + "/" + track.name, o, {});
    summary += "## Track " + track.name + " (" + track.name + "/)\n\n";
    for (const std::string& note : track.notes) summary += "- " + note + "\n";
    summary += "\n" + Demoted(outcome.summary) + "\n";
  }
  if (ranks::Rank() == 0) WriteFileAtomically(o.out + "/summary.md", summary);
}

void RunCompare(const CompareOptions& o) {
  if (o.quick && !o.suite.empty() && !IsSuiteName(o.suite))
    throw InputError(
        "compare: --quick makes an embedded suite seconds-long; a suite file sets "
        "its own size (give --suite FILE without --quick)");
  if (!o.cv.empty() && o.cv != kCrossValidationRuns)
    throw InputError("compare: --cv '" + o.cv + "' is unknown (known: " + kCrossValidationRuns +
                     ", leave one run out)");
  if (o.suite == "real") return RunRealSuite(o);
  const EmbeddedSuite* embedded = FindEmbeddedSuite(o.suite.empty() ? "default" : o.suite);
  if (!o.cv.empty() && embedded != nullptr)
    throw InputError("compare: --cv " + o.cv + ": suite '" +
                     (o.suite.empty() ? std::string(o.quick ? "quick" : "default") : o.suite) +
                     "' is simulated and has no runs to leave out (a suite on measured data has; "
                     "docs/compare.md#cross-validation-over-runs)");
  if (embedded == nullptr && IsSuiteName(o.suite))
    throw InputError("compare: --suite '" + o.suite + "' is no embedded suite (" +
                     EmbeddedSuiteNames() + ") and no suite file (a path with .json)");
  Suite suite;
  if (embedded != nullptr) {
    suite = LoadEmbeddedSuite(*embedded, o.quick);
  } else {
    nlohmann::json json = ReadJsonFile(o.suite, JsonComments::kAllowed);
    if (!o.cv.empty() && json.is_object()) json["cv"] = o.cv;
    suite = ParseSuite(json, o.suite);
  }
  // The baseline is read before hours of fitting, not after.
  const nlohmann::json baseline = o.baseline.empty() ? nlohmann::json() : ReadJsonFile(o.baseline);
  const SuiteOutcome outcome = RunSuiteInto(suite, o.out, o, baseline);
  if (outcome.worse > 0)
    throw RegressionFound("compare: " + std::to_string(outcome.worse) +
                          " groups worse than the baseline " + o.baseline + " (see " + o.out +
                          "/regressions.json)");
}

}  // namespace

void AddCompareCommand(CLI::App& app) {
  auto o = std::make_shared<CompareOptions>();
  CLI::App* cmd = app.add_subcommand(
      "compare", "The benchmark: methods x maneuvers x vessels x noise x seeds, held-out scores");
  cmd->add_option("--suite", o->suite,
                  "A suite JSON file, or an embedded suite: " + EmbeddedSuitesHelp());
  cmd->add_option("--data-dir", o->data_dir,
                  "The measured data of --suite real (default ../shared/data); absent, the suite "
                  "is skipped");
  cmd->add_flag("--quick", o->quick,
                "The default suite, smaller: seconds, not minutes; with --suite realistic, "
                "realistic-measured or real, that suite's seconds-long variant (its records and "
                "checks, fewer fits: harness/smoke_suite.h)");
  cmd->add_option("--cv", o->cv,
                  "runs: leave-one-run-out cross-validation of a suite on measured data (--suite "
                  "real, or a suite file with \"data\"): each run left out in turn, every method "
                  "fitted on the others and scored on it; summary.md and results.json gain the "
                  "means over the runs with bootstrap intervals");
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
  cmd->add_flag_callback(
      "--fields",
      [] {
        std::cout << SuiteFieldsMarkdown();
        throw CLI::Success();
      },
      "Print the fields of a suite file, each with its default and what it holds, as "
      "docs/suites.md (generated from harness/suite_fields.h), and exit");
  cmd->callback([o] { RunCompare(*o); });
}

}  // namespace usvid
