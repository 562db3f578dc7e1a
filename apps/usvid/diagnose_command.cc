// usvid diagnose --data F.csv --vessel V [--params P.json] --out DIR
// What the nominal simulation gets wrong on F, the cause (an effect of the catalogue, or none),
// the extended model and the gain on held-out data: DIR/diagnosis.json, DIR/model.json and
// DIR/report.html with its plots.

#include <omp.h>

#include <iostream>
#include <memory>

#include "apps/usvid/commands.h"
#include "apps/usvid/data_file.h"
#include "core/atomic_file.h"
#include "core/csv_dataset.h"
#include "core/error.h"
#include "core/json_file.h"
#include "diagnosis/diagnose.h"
#include "diagnosis/diagnosis_json.h"
#include "diagnosis/diagnosis_report.h"
#include "simulation/vessel_ref.h"

namespace usvid {
namespace {

struct DiagnoseCliOptions {
  std::string data;
  std::string vessel;
  std::string params;
  std::string out;
  diagnosis::DiagnoseOptions options;
  int threads = 0;
};

void RunDiagnose(const DiagnoseCliOptions& o) {
  const VesselRef vessel(o.vessel);
  const std::vector<double> params =
      o.params.empty() ? vessel.Info().default_params : vessel.Info().ParamsFromFile(o.params);
  diagnosis::DiagnoseOptions options = o.options;
  // A model diagnosed before brings its effects: the next diagnosis starts from them.
  if (!o.params.empty()) options.base_effects = EffectsOfFile(o.params);
  if (options.max_causes < 1) throw InputError("--causes must be at least 1");
  if (o.threads < 0) throw InputError("--threads must be 0 (all cores) or more");
  const Dataset data = ReadDataFile(o.data, "usvid diagnose");
  EnsureOutputDirectory(o.out);
  const diagnosis::Diagnosis d = diagnosis::Diagnose(data, vessel, params, options, &std::cerr);
  diagnosis::WriteDiagnosisReport(d, o.out);
  WriteJsonFile(o.out + "/model.json", diagnosis::ExtendedModelJson(d));
  WriteJsonFile(o.out + "/diagnosis.json", diagnosis::DiagnosisToJson(d));
  std::cerr << "usvid diagnose: cause " << d.cause << ", held-out error reduction "
            << d.heldout_error_reduction << " (" << d.seconds << " s); wrote " << o.out
            << "/diagnosis.json, model.json, report.html\n";
}

}  // namespace

void AddDiagnoseCommand(CLI::App& app) {
  auto o = std::make_shared<DiagnoseCliOptions>();
  CLI::App* cmd = app.add_subcommand(
      "diagnose",
      "What the nominal simulation gets wrong on measured data, its cause, the extended model "
      "and the held-out gain");
  cmd->add_option("--data", o->data, "Measured data CSV (the vessel's inputs and states)")
      ->required();
  cmd->add_option("--vessel", o->vessel, "Nominal simulator: " + VesselChoices())->required();
  cmd->add_option("--params", o->params,
                  "JSON of nominal parameter overrides, or a truth/model file's \"parameters\" "
                  "(a diagnose model.json brings its \"effects\" too: diagnose it again)");
  cmd->add_option("--causes", o->options.max_causes,
                  "Most causes to name: while those named leave much of the error, the "
                  "extended model is diagnosed again")
      ->capture_default_str();
  cmd->add_option("--out", o->out, "Directory for diagnosis.json, model.json, report.html")
      ->required();
  cmd->add_option(
         "--segment", o->options.split.segment_s,
         "Segment length [s]: each segment is simulated from its own initial state, estimated "
         "from the data (0: 1.5 hull lengths of travel, at least 10 s)")
      ->capture_default_str();
  cmd->add_option("--heldout", o->options.split.heldout_fraction,
                  "Fraction of the record (its end) held out for scoring")
      ->capture_default_str();
  cmd->add_option("--fit-rows", o->options.split.max_fit_rows,
                  "Most rows the candidate effects are fitted on (the training part's last) "
                  "and scored on (the held-out part's first); 0: all rows")
      ->capture_default_str();
  cmd->add_option("--dt", o->options.split.max_step,
                  "Largest integration step [s] (0: the data's interval, at most 0.05 s)")
      ->capture_default_str();
  cmd->add_option("--threads", o->threads, "OpenMP threads (0: all cores)");
  cmd->callback([o] {
    if (o->threads > 0) omp_set_num_threads(o->threads);
    RunDiagnose(*o);
  });
}

}  // namespace usvid
