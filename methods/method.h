// An identification method as the rest of usvid sees it: a name, a line of help, and a function
// from data to model.json. Registered in one place (methods/method_list.h); `usvid identify`,
// `compare`'s suites and `--help` find methods there, never by spelling their names
// (docs/adding-a-method.md).
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "core/dataset.h"
#include "methods/identify_request.h"
#include "methods/method_options.h"

namespace usvid {

// Receives progress lines (may be empty).
using Logger = std::function<void(const std::string&)>;

inline void Log(const Logger& log, const std::string& line) {
  if (log) log(line);
}

struct Method {
  std::string name;     // as --method and suites spell it
  std::string summary;  // one line for --help
  // Its options, declared once (methods/method_options.h): the command line, suites, Python and
  // docs/options.md are made from this list.
  std::vector<OptionSpec> options;
  // model.json of the method fitted to `data` (speed, course and the request's forces already
  // derived) with `options` (the request's, checked against the declaration): at least method,
  // vessel, states, inputs, parameters and train, and "options" when a preset made the options
  // it ran with other than the declared defaults. It must read every option it declares.
  // Throws InputError for channels or data the method cannot take.
  std::function<nlohmann::json(const Dataset& data, const IdentifyRequest& request,
                               const MethodOptions& options, const Logger& log)>
      identify;
  // Takes its inputs as channels, so that a waterjet log's jet forces may stand in for the
  // commands (the suite's default input map). Vessel models take the vessel's own inputs.
  bool channel_inputs = false;
  // Its equations may take any channel as one more input: a suite whose records log their
  // disturbances (the wind, the current) hands it those channels beside its own inputs.
  bool any_inputs = false;
  // Reads the request's channels (states, inputs) and preprocessing (rate, derivative, forces):
  // a suite entry or Python call may give those keys only to a method that reads them.
  bool named_channels = true;
  bool preprocessed = true;
  // Its result depends on the seed: on measured data, where the data do not change with the
  // seed, a suite fits it once per seed, the other methods once.
  bool seeded = false;
  // A suite option shown in the row's label, as name[value] (gp[+,-,*,abs]); "" none.
  std::string label_option;
  // A fit's rough cost against a regression's (1) at the method's defaults: a suite starts its
  // costliest fits first, so that no core waits at the end behind one long fit
  // (harness/run_suite.h, SlowestFirst). `cost_scale` (may be empty) scales it by the options
  // (gp: population x generations against its defaults').
  double relative_cost = 1.0;
  std::function<double(const MethodOptions& options)> cost_scale;
};

}  // namespace usvid
