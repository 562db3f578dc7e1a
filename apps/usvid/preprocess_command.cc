// usvid preprocess --data F.csv --states u,v,r --inputs tau_x,tau_y,tau_n [--rate HZ]
//                  [--derivative sg:21:3|spline|tv|euler] [--delay auto|SECONDS] --out G.csv
// The preprocessing of `usvid identify`, on its own: resampled, smoothed states, their
// derivatives as <state>_dot, the raw states as <state>_raw, inputs shifted by the delay.

#include <iostream>
#include <memory>

#include "apps/usvid/commands.h"
#include "apps/usvid/data_file.h"
#include "apps/usvid/preprocess_options.h"
#include "core/csv_dataset.h"
#include "preprocessing/pipeline.h"
#include "preprocessing/waterjet_forces.h"

namespace usvid {
namespace {

struct PreprocessCommandOptions {
  std::string data;
  std::vector<std::string> states, inputs;
  PreprocessFlags flags;
  std::string out;
};

void RunPreprocess(const PreprocessCommandOptions& o) {
  Dataset data = ReadDataFile(o.data, "usvid preprocess");
  SimulateMissingActuators(data, o.flags.actuators);
  AddForces(data, o.flags.forces);
  const PreparedData prepared = Preprocess(data, o.states, o.inputs, o.flags.Options());
  for (const std::string& note : prepared.notes) std::cerr << "usvid preprocess: " << note << '\n';
  WriteDatasetCsv(o.out, prepared.data);
  std::cerr << "usvid preprocess: wrote " << o.out << '\n';
}

}  // namespace

void AddPreprocessCommand(CLI::App& app) {
  auto o = std::make_shared<PreprocessCommandOptions>();
  CLI::App* cmd = app.add_subcommand(
      "preprocess", "Resample, estimate and remove the input delay, smooth and differentiate");
  cmd->add_option("--data", o->data, "Data CSV")->required();
  cmd->add_option("--states", o->states, "State channels to differentiate")
      ->delimiter(',')
      ->required();
  cmd->add_option("--inputs", o->inputs, "Input channels")->delimiter(',')->required();
  o->flags.Add(*cmd);
  cmd->add_option("--out", o->out, "CSV to write")->required();
  cmd->callback([o] { RunPreprocess(*o); });
}

}  // namespace usvid
