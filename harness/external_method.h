// A suite's external method: a command outside usvid (a Python script, say) fitted like any
// other row. The suite names it {"method": "external", "name": "mine", "command": ["python3",
// "mine.py"], "timeout_s": 600}; the harness writes the training record to a temporary folder
// and runs
//   COMMAND... --data TRAIN.csv --states u,v,r --inputs tau_x,tau_y,tau_n --out MODEL.json
// then scores the model.json it wrote (docs/data.md#modeljson) on the held-out tests. A command
// that cannot start, exits non-zero, outlives its timeout (it and its children are killed) or
// writes no valid model.json is an InputError saying which, with the last line it printed on
// stderr; the harness makes that the cell's failed rows, and the rest of the suite runs on.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "core/dataset.h"

namespace usvid {

// The suite's method name for an external command (beside the registered methods).
inline constexpr std::string_view kExternalMethod = "external";

struct ExternalCommand {
  std::string name;                  // the row's label
  std::vector<std::string> command;  // program and its first arguments
  double timeout_s = 600.0;
};

// The command's fields from a suite's method options ("name", "command", "timeout_s"; the
// rest is the common options' business). Throws InputError naming `where` and the field.
ExternalCommand ParseExternalCommand(const nlohmann::json& options, const std::string& where);

// Runs the command on `train` and returns the model.json it wrote, with "method" set to
// "external:NAME" when the command left it out. The temporary folder is removed either way.
nlohmann::json IdentifyExternal(const ExternalCommand& command, const Dataset& train,
                                const std::vector<std::string>& states,
                                const std::vector<std::string>& inputs);

}  // namespace usvid
