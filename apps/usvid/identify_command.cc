// usvid identify --method M --data F.csv[,G.csv...] (--vessel V | --states u,v,r --inputs a,b)
//                [preprocessing flags] [the method's options: docs/options.md]
//                [--seed N] [--threads N] --out model.json
// Fits one method and writes model.json (docs/data.md#modeljson). Every method's options are
// flags made from its declaration (methods/method_options.h): max_depth is --max-depth.

#include <algorithm>
#include <iostream>
#include <map>
#include <memory>

#include "apps/usvid/commands.h"
#include "apps/usvid/data_file.h"
#include "apps/usvid/preprocess_options.h"
#include "core/atomic_file.h"
#include "core/csv_dataset.h"
#include "core/error.h"
#include "core/json_file.h"
#include "core/model_view.h"
#include "core/parse_number.h"
#include "harness/fit_service.h"
#include "methods/identify.h"
#include "methods/registry.h"
#include "preprocessing/waterjet_forces.h"
#include "simulation/vessel_simulator.h"

namespace usvid {
namespace {

// Earlier spellings of option flags, still accepted.
const std::map<std::string, std::string> kOldFlags = {{"horizon_s", "--horizon"},
                                                      {"segment_s", "--segment"}};

struct IdentifyOptions {
  IdentifyRequest request;  // the method, seed and threads given (the rest: FitRequest)
  std::string vessel;       // --vessel, resolved by FitRequest
  std::string data;
  std::string params;
  PreprocessFlags pre;
  std::string out;
  // Every method's option flags, by key: the text given (a switch: "true"; a list, its items,
  // comma- or space-separated), and the flag.
  std::map<std::string, std::string> texts;
  std::map<std::string, std::vector<std::string>> lists;
  std::map<std::string, bool> switches;
  std::map<std::string, const CLI::Option*> flags;
};

// The option flags given, read as the chosen method declares them (and the keys every method
// shares, as SharedFitOptions declares them); a flag the method does not declare is an error
// naming it and the method's options.
nlohmann::json GivenOptions(const IdentifyOptions& o) {
  const Method& method = FindMethod(o.request.method);
  nlohmann::json options = nlohmann::json::object();
  for (const auto& [key, flag] : o.flags) {
    if (flag->count() == 0) continue;
    const std::vector<OptionSpec>& declared =
        IsSharedFitKey(key) ? SharedFitOptions() : method.options;
    const auto spec =
        std::ranges::find_if(declared, [&](const OptionSpec& s) { return s.key == key; });
    if (spec == declared.end()) {
      std::string flags;
      for (const OptionSpec& s : method.options) flags += (flags.empty() ? "" : ", ") + s.Flag();
      throw InputError(flag->get_name() + ": method " + method.name + " has no option '" + key +
                       "' (its options: " + (flags.empty() ? "none" : flags) + ")");
    }
    std::string text = spec->type == OptionType::kFlag ? "true" : "";
    if (spec->type == OptionType::kList)
      for (const std::string& item : o.lists.at(key)) text += (text.empty() ? "" : ",") + item;
    else if (spec->type != OptionType::kFlag)
      text = o.texts.at(key);
    const nlohmann::json value = OptionFromText(method.name, *spec, text);
    // Checked here, so that the message names the flag as well as the key.
    ValidateOptions(method.name, {*spec}, {{key, value}}, flag->get_name());
    options[key] = value;
  }
  return options;
}

void RunIdentify(const IdentifyOptions& o) {
  CheckOutputFile(o.out);
  // The request as a suite's or Python's is made (harness/fit_service.h), over the preprocessing
  // only the command line has (--interpolation, --delay, ...).
  IdentifyRequest r =
      FitRequest(o.request.method, GivenOptions(o), o.vessel, o.request.seed, o.pre.Options());
  r.threads = o.request.threads;
  CheckedOptions(FindMethod(r.method), r, "usvid identify");  // before the data are read
  r.data_name = o.data;
  if (!o.params.empty()) {
    if (r.vessel.empty()) throw InputError("--params: needs --vessel");
    r.start_params = r.vessel.Info().ParamsFromFile(o.params);
  }
  // Every record needs the named channels, except those identify derives (speed and course,
  // and a force map's forces when one is given).
  std::vector<std::string> required;
  const bool forces = !r.preprocess.forces.empty();
  for (const auto* names : {&r.states, &r.inputs})
    for (const std::string& c : *names)
      if (c != "U" && c != "chi" &&
          !(forces && std::ranges::find(kWaterjetForceChannels, c) != kWaterjetForceChannels.end()))
        required.push_back(c);
  Dataset data = ReadDataFiles(o.data, "usvid identify", required, [&](Dataset& record) {
    SimulateMissingActuators(record, o.pre.actuators);
  });
  nlohmann::json model = Fit(FindMethod(r.method), data, r, [](const std::string& line) {
    std::cerr << "usvid identify: " << line << '\n';
  });
  const ModelView view(model);
  if (const nlohmann::json& c = view.Calibration("yaw_bias"); c.is_object()) {
    std::cerr << "usvid identify: r's constant from the training zig-zags' overshoots: "
              << (c.value("applied", false)
                      ? FormatNumber(c["constant_before"].get<double>()) + " -> " +
                            FormatNumber(c["constant_after"].get<double>())
                      : "kept, " + c.value("reason", std::string()))
              << '\n';
  }
  WriteJsonFile(o.out, model);
  for (const std::string& state : view.EquationStates())
    std::cerr << "usvid identify: " << state << "' = " << view.Equation(state).value_or("?")
              << '\n';
  std::cerr << "usvid identify: wrote " << o.out << " (" << view.TrainSeconds() << " s)\n";
}

// One flag per option key of any method, and per key every method shares. Its help gives each
// declaring method's line and default, once for methods that say the same (refit and hybrid
// share refit's options).
void AddMethodOptionFlags(CLI::App& cmd, IdentifyOptions& o) {
  std::vector<std::string> keys;
  std::map<std::string, std::vector<std::pair<std::string, std::string>>> lines;  // text, methods
  std::map<std::string, const OptionSpec*> first;
  for (const OptionSpec& s : SharedFitOptions()) {
    keys.push_back(s.key);
    first[s.key] = &s;
    lines[s.key].push_back({s.help, "every method"});
  }
  for (const Method& m : Methods())
    for (const OptionSpec& s : m.options) {
      if (!first.contains(s.key)) {
        keys.push_back(s.key);
        first[s.key] = &s;
      }
      const std::string text =
          s.help + (s.type == OptionType::kFlag ? "" : " (default " + s.DefaultText() + ")");
      auto& said = lines[s.key];
      const auto same = std::ranges::find_if(said, [&](const auto& l) { return l.first == text; });
      if (same == said.end())
        said.push_back({text, m.name});
      else
        same->second += ", " + m.name;
    }
  for (const std::string& key : keys) {
    const OptionSpec& s = *first[key];
    std::string help;
    for (const auto& [text, methods] : lines[key])
      help += (help.empty() ? "" : "; ") + methods + ": " + text;
    std::string names = s.Flag();
    if (const auto old = kOldFlags.find(key); old != kOldFlags.end()) names += "," + old->second;
    if (s.type == OptionType::kFlag) {
      o.flags[key] = cmd.add_flag(names, o.switches[key], help);
      continue;
    }
    CLI::Option* flag = s.type == OptionType::kList
                            ? cmd.add_option(names, o.lists[key], help)->delimiter(',')
                            : cmd.add_option(names, o.texts[key], help);
    flag->type_name(s.type == OptionType::kInteger  ? "INT"
                    : s.type == OptionType::kNumber ? "FLOAT"
                    : s.type == OptionType::kList   ? "A,B,..."
                                                    : "TEXT");
    o.flags[key] = flag;
  }
}

}  // namespace

void AddIdentifyCommand(CLI::App& app) {
  auto o = std::make_shared<IdentifyOptions>();
  CLI::App* cmd = app.add_subcommand("identify", "Fit one identification method to data");
  std::string methods_help;
  std::vector<std::string> names;
  for (const Method& m : Methods()) {
    methods_help += (methods_help.empty() ? "" : "; ") + m.name + " (" + m.summary + ")";
    names.push_back(m.name);
  }
  cmd->add_option("--method", o->request.method, methods_help)
      ->required()
      ->check(CLI::IsMember(names));
  cmd->add_option("--data", o->data,
                  "Training data CSV, or several (a.csv,b.csv,...) fitted jointly")
      ->required();
  cmd->add_option("--vessel", o->vessel,
                  "Take states and inputs from this simulator: " + VesselChoices());
  o->pre.Add(*cmd, /*fit_keys=*/false);
  AddMethodOptionFlags(*cmd, *o);
  cmd->add_option("--seed", o->request.seed, "Seed of the search");
  cmd->add_option("--threads", o->request.threads, "OpenMP threads (0: all cores)");
  cmd->add_option("--params", o->params,
                  "refit, hybrid, nominal: starting parameters (JSON of name: value, or a model's "
                  "\"parameters\"); default the vessel's");
  cmd->add_option("--out", o->out, "model.json to write")->required();
  cmd->callback([o] { RunIdentify(*o); });
}

}  // namespace usvid
