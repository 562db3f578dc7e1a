#include "harness/suite.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <type_traits>

#include "core/error.h"
#include "effects/effect.h"
#include "effects/effect_values.h"
#include "harness/cross_validation.h"
#include "maneuvers/maneuver_factory.h"
#include "maneuvers/maneuver_spec.h"
#include "methods/registry.h"
#include "preprocessing/derivative.h"
#include "sensors/dropouts.h"
#include "sensors/sample_rates.h"
#include "sensors/wave_motion.h"
#include "simulation/logged_disturbances.h"
#include "simulation/vessel_simulator.h"
#include "simulation/wind_gusts.h"

namespace usvid {
namespace {

template <typename T>
std::vector<T> ListOf(const nlohmann::json& v, const std::string& where) {
  if (!v.is_array() || v.empty()) throw InputError(where + ": expected a non-empty array");
  std::vector<T> out;
  for (const auto& item : v) {
    // Integers must be integers in range: nlohmann would turn 1e128 or -1 into some uint64_t.
    const bool fits =
        !std::is_integral_v<T> ||
        (item.is_number_integer() &&
         (!std::is_unsigned_v<T> || item.is_number_unsigned() || item.get<int64_t>() >= 0));
    try {
      if (!fits) throw InputError("");
      out.push_back(item.get<T>());
    } catch (const std::exception&) {
      throw InputError(where + ": element " + item.dump() + " has the wrong type" +
                       (std::is_unsigned_v<T> ? " (expected a whole number >= 0)" : ""));
    }
  }
  return out;
}

}  // namespace

void CheckSuiteMethod(const SuiteMethod& method, const std::string& where) {
  // The method's options, and the shared keys it reads (methods/method.h: named_channels,
  // preprocessed).
  const Method& m = FindSuiteMethod(method.method);
  std::vector<OptionSpec> specs = m.options;
  for (const OptionSpec& shared : SharedFitOptions()) {
    const bool channels = shared.key == "states" || shared.key == "inputs";
    if (!(channels ? m.named_channels : m.preprocessed)) continue;
    // The shared keys a method declares itself (none today) stay its own.
    if (std::ranges::none_of(specs, [&](const OptionSpec& s) { return s.key == shared.key; }))
      specs.push_back(shared);
  }
  ValidateOptions(method.method, specs, method.options, where);
  if (method.options.contains("derivative")) {  // a string, as checked
    try {
      DerivativeMethod::Parse(method.options["derivative"].get<std::string>());
    } catch (const InputError& e) {
      throw InputError(where + ": method " + method.method + ": option 'derivative': " + e.what());
    }
  }
  if (method.method == kExternalMethod) {
    const ExternalCommand c = ParseExternalCommand(method.options, where + ": " + method.method);
    if (std::ranges::any_of(SuiteMethods(), [&](const Method& m) { return m.name == c.name; }))
      throw InputError(where + ": external name '" + c.name +
                       "' is a usvid method's; choose another");
  }
}

namespace {

std::vector<SuiteData> DataList(const nlohmann::json& v, const std::string& file,
                                const std::string& where) {
  if (!v.is_array() || v.empty())
    throw InputError(file + ": " + where + ": expected a non-empty array");
  const std::string dir = std::filesystem::path(file).parent_path().string();
  std::vector<SuiteData> out;
  for (size_t i = 0; i < v.size(); ++i)
    out.push_back(ParseSuiteData(v[i], dir, file + ": " + where + "[" + std::to_string(i) + "]"));
  return out;
}

// A suite on measured data: its training and test files, and at most one vessel. A
// cross-validated suite (`cv`) may leave out "test": every run is held out in turn.
void ParseMeasuredData(const nlohmann::json& v, const std::string& file, bool cv, Suite& s) {
  const nlohmann::json& data = v["data"];
  if (!data.is_object() || !data.contains("train") || (!cv && !data.contains("test")))
    throw InputError(file + ": data: expected {\"train\": [...], \"test\": [...]}");
  for (const auto& [key, _] : data.items())
    if (key != "train" && key != "test")
      throw InputError(file + ": data: unknown field '" + key + "'");
  for (const char* key : {"train_maneuvers", "test_maneuvers", "train_seconds", "test_seconds"})
    if (v.contains(key))
      throw InputError(file + ": '" + key + "' does not apply to a suite on measured data");
  s.train_data = DataList(data["train"], file, "data: train");
  if (data.contains("test")) s.test_data = DataList(data["test"], file, "data: test");
  for (const SuiteData& d : s.test_data)
    if (d.files.size() > 1)  // a test is one free run, which no gap may cut
      throw InputError(file + ": data: test: '" + d.name +
                       "': a test entry is one file (a list of files joins records for training)");
  for (const SuiteData& d : s.train_data) s.train_maneuvers.push_back(d.name);
  for (const SuiteData& d : s.test_data) s.test_maneuvers.push_back(d.name);
  if (v.contains("vessels")) {
    if (!v["vessels"].is_array()) throw InputError(file + ": vessels: expected an array");
    for (const auto& item : v["vessels"]) {
      if (!item.is_string()) throw InputError(file + ": vessels: names are strings");
      s.vessels.push_back(item.get<std::string>());
    }
  }
  if (s.vessels.size() > 1)
    throw InputError(file + ": a suite on measured data has at most one vessel");
}

// The methods: names, or objects with "method" and its options.
std::vector<SuiteMethod> ParseMethods(const nlohmann::json& list, const std::string& file) {
  if (!list.is_array() || list.empty())
    throw InputError(file + ": methods: expected a non-empty array");
  std::vector<SuiteMethod> methods;
  for (const auto& m : list) {
    SuiteMethod sm;
    if (m.is_string()) {
      sm.method = m.get<std::string>();
      sm.options = nlohmann::json::object();
    } else if (m.is_object() && m.contains("method") && m["method"].is_string()) {
      sm.method = m["method"].get<std::string>();
      sm.options = m;
      sm.options.erase("method");
    } else {
      throw InputError(file + ": methods: each is a name or an object with \"method\"");
    }
    try {
      FindSuiteMethod(sm.method);
    } catch (const InputError& e) {
      throw InputError(file + ": methods: " + e.what());
    }
    CheckSuiteMethod(sm, file + ": methods");
    methods.push_back(sm);
  }
  return methods;
}

}  // namespace

nlohmann::json SuiteMethod::OwnOptions() const { return OwnFitOptions(options); }

std::string SuiteMethod::Label() const {
  if (method == kExternalMethod) return options.at("name").get<std::string>();
  // A grey-box fit (GP's corrections to a vessel, docs/gp.md#grey-box) is another model than
  // the method's own: "gp+vessel".
  const std::string name = options.contains("base") && options.at("base").is_string()
                               ? method + "+" + options.at("base").get<std::string>()
                               : method;
  const std::string& option = FindSuiteMethod(method).label_option;
  if (option.empty() || !options.contains(option)) return name;
  const nlohmann::json& value = options.at(option);
  if (value.is_string()) return name + "[" + value.get<std::string>() + "]";
  std::string text;  // a list given as an array
  for (const auto& item : value) text += (text.empty() ? "" : ",") + item.get<std::string>();
  return name + "[" + text + "]";
}

std::string FitJob::Id() const {
  std::ostringstream s;
  s << vessel << "/" << train_maneuver << "/" << method.Label() << "/noise=" << noise
    << "/seed=" << seed;
  return s.str();
}

namespace {

// "effects", "sensors", "gusts", "waves", "dropouts" and "logged" (SuiteConditions), checked on
// every vessel of the suite before any fit: an effect the vessel cannot take (wind without a wind
// model, an input or state it lacks), waves on a vessel without positions and body velocities, a
// sensor naming no group or channel of its records, or a logged disturbance that the conditions
// do not make is an error naming the field.
void ParseConditions(const nlohmann::json& v, const std::string& file, Suite& s) {
  if (!v.contains("effects") && !v.contains("sensors") && !v.contains("gusts") &&
      !v.contains("waves") && !v.contains("dropouts") && !v.contains("logged"))
    return;
  if (s.Measured())
    throw InputError(file + ": 'effects', 'sensors', 'gusts', 'waves', 'dropouts' and 'logged' " +
                     "make simulated records; measured data have their own");
  if (v.contains("effects"))
    s.conditions.effects = ListOf<std::string>(v["effects"], file + ": effects");
  if (v.contains("sensors"))
    s.conditions.sensors = ListOf<std::string>(v["sensors"], file + ": sensors");
  if (v.contains("dropouts"))
    s.conditions.dropouts = ListOf<std::string>(v["dropouts"], file + ": dropouts");
  if (v.contains("logged"))
    s.conditions.logged = ListOf<std::string>(v["logged"], file + ": logged");
  if (v.contains("waves")) {
    if (!v["waves"].is_string())
      throw InputError(file + ": 'waves' must be a string, HS[:TP[:FROM_DEG]]");
    s.conditions.waves = v["waves"].get<std::string>();
  }
  if (v.contains("gusts")) {
    if (!v["gusts"].is_string())
      throw InputError(file + ": 'gusts' must be a string, SPEED[:FROM_DEG]");
    s.conditions.gusts = v["gusts"].get<std::string>();
  }
  std::vector<Effect> effects;
  std::vector<Dropout> dropouts;
  std::optional<WaveSea> sea;
  try {
    effects = ParseEffects(s.conditions.effects, 1);
  } catch (const InputError& e) {
    throw InputError(file + ": effects: " + e.what());
  }
  CheckLoggedDisturbances(s.conditions.logged, !s.conditions.gusts.empty(), effects,
                          file + ": logged");
  try {
    dropouts = ParseDropouts(s.conditions.dropouts);
    if (!s.conditions.waves.empty()) sea = ParseWaveSea(s.conditions.waves, 1, "waves");
  } catch (const InputError& e) {
    throw InputError(file + ": " + e.what());
  }
  for (const std::string& vessel : s.vessels) {
    const VesselInfo& info = FindVessel(vessel).Info();
    try {
      for (const Effect& e : effects)
        if (e.kind == EffectKind::kWind && !info.wind_body)
          throw InputError("vessel " + info.name + " has no wind model");
      ValuesOf(effects, info.inputs, info.states);
    } catch (const InputError& e) {
      throw InputError(file + ": effects: " + e.what());
    }
    if (!s.conditions.gusts.empty()) MakeWindGusts(info, s.conditions.gusts, 1, file + ": gusts");
    // The channels a simulated record of the vessel holds, one row: what a sensor may name.
    Dataset record(Eigen::VectorXd::Zero(1));
    for (const std::vector<std::string>* names : {&info.states, &info.derived, &info.inputs})
      for (const std::string& name : *names) record.Set(name, Eigen::VectorXd::Zero(1));
    try {
      ParseSampleRates(s.conditions.sensors, record);
      ApplyDropouts(record, dropouts, 1);
      if (sea) AddWaveMotion(record, *sea, 0.0, 1);
    } catch (const InputError& e) {
      throw InputError(file + ": sensors: " + info.name + ": " + e.what());
    }
  }
}

// "pairs": a list of two method names, each a method of the suite, the two different.
std::vector<std::array<std::string, 2>> ParsePairs(const nlohmann::json& v,
                                                   const std::vector<SuiteMethod>& methods,
                                                   const std::string& file) {
  const std::string what = file + ": pairs: ";
  if (!v.is_array()) throw InputError(what + "must be a list of pairs of method names");
  std::vector<std::array<std::string, 2>> pairs;
  for (const nlohmann::json& p : v) {
    if (!p.is_array() || p.size() != 2 || !p[0].is_string() || !p[1].is_string())
      throw InputError(what + "each pair is two method names, as [\"gp\", \"eb-lr\"], got " +
                       p.dump());
    std::array<std::string, 2> pair{p[0].get<std::string>(), p[1].get<std::string>()};
    if (pair[0] == pair[1]) throw InputError(what + "a pair of '" + pair[0] + "' with itself");
    for (const std::string& name : pair)
      if (std::none_of(methods.begin(), methods.end(),
                       [&](const SuiteMethod& m) { return m.method == name; }))
        throw InputError(what + "'" + name + "' is not among the suite's methods");
    pairs.push_back(pair);
  }
  return pairs;
}

}  // namespace

Suite ParseSuite(const nlohmann::json& v, const std::string& file) {
  if (!v.is_object()) throw InputError(file + ": a suite is a JSON object");
  static const std::set<std::string> kFields = {
      "name",  "vessels",       "train_maneuvers", "test_maneuvers", "methods", "noise",
      "seeds", "train_seconds", "test_seconds",    "data",           "effects", "sensors",
      "gusts", "waves",         "dropouts",        "logged",         "cv",      "pairs"};
  for (const auto& [key, _] : v.items())
    if (!kFields.contains(key)) throw InputError(file + ": unknown field '" + key + "'");
  const bool measured = v.contains("data");
  for (const char* required : {"vessels", "train_maneuvers", "test_maneuvers", "methods"}) {
    if (measured && std::string(required) != "methods") continue;
    if (!v.contains(required)) throw InputError(file + ": missing field '" + required + "'");
  }
  Suite s;
  if (v.contains("name")) {
    if (!v["name"].is_string()) throw InputError(file + ": 'name' must be a string");
    s.name = v["name"].get<std::string>();
  }
  std::string cv;
  if (v.contains("cv")) {
    if (!v["cv"].is_string())
      throw InputError(file + ": 'cv' must be a string (\"" + kCrossValidationRuns + "\")");
    cv = v["cv"].get<std::string>();
    if (!measured)
      throw InputError(file + ": cv: a simulated suite has no runs to leave out (cv needs a " +
                       "suite on measured data, \"data\": {...})");
  }
  if (measured) {
    ParseMeasuredData(v, file, !cv.empty(), s);
    if (!cv.empty()) ExpandCrossValidation(s, cv, file);
  } else {
    s.vessels = ListOf<std::string>(v["vessels"], file + ": vessels");
    s.train_maneuvers = ListOf<std::string>(v["train_maneuvers"], file + ": train_maneuvers");
    s.test_maneuvers = ListOf<std::string>(v["test_maneuvers"], file + ": test_maneuvers");
  }
  // A vessel file is named relative to the suite, as its data are.
  for (std::string& vessel : s.vessels)
    if (IsVesselFile(vessel))
      vessel = SuitePath(std::filesystem::path(file).parent_path().string(), vessel);
  for (const std::string& vessel : s.vessels) FindVessel(vessel);  // throws on unknown names
  // Unknown maneuvers are refused here, before any fit: a spec must run on at least one of the
  // suite's vessels (a zig-zag needs a heading, which not every vessel has).
  auto check_maneuver = [&](const std::string& spec, const std::string& where) {
    std::string why;
    for (const std::string& vessel : s.vessels) {
      try {
        MakeManeuver(spec, FindVessel(vessel).Info().actuation, 0.0, 1);
        return;
      } catch (const InputError& e) {
        if (why.empty()) why = e.what();
      }
    }
    if (!why.empty()) throw InputError(file + ": " + where + ": " + why);
  };
  if (measured) {
    for (const SuiteData& d : s.test_data)
      if (!d.maneuver.empty()) check_maneuver(d.maneuver, "data: test: " + d.name);
  } else {
    for (const std::string& m : s.train_maneuvers) check_maneuver(m, "train_maneuvers");
    for (const std::string& m : s.test_maneuvers) check_maneuver(m, "test_maneuvers");
  }
  s.methods = ParseMethods(v["methods"], file);
  if (v.contains("pairs")) s.pairs = ParsePairs(v["pairs"], s.methods, file);
  s.noise = v.contains("noise") ? ListOf<double>(v["noise"], file + ": noise")
                                : std::vector<double>{measured ? 0.0 : 0.005};
  for (double n : s.noise)
    if (!(n >= 0 && n < 1)) throw InputError(file + ": noise: levels must be in [0, 1)");
  s.seeds = v.contains("seeds") ? ListOf<uint64_t>(v["seeds"], file + ": seeds")
                                : std::vector<uint64_t>{1};
  ParseConditions(v, file, s);
  for (const char* key : {"train_seconds", "test_seconds"}) {
    if (!v.contains(key)) continue;
    if (!v[key].is_number() || !(v[key].get<double>() > 0))
      throw InputError(file + ": '" + key + "' must be a positive number");
    (std::string(key) == "train_seconds" ? s.train_seconds : s.test_seconds) = v[key].get<double>();
  }
  return s;
}

nlohmann::json SuiteToJson(const Suite& s) {
  nlohmann::json methods = nlohmann::json::array();
  for (const SuiteMethod& m : s.methods) {
    nlohmann::json j = m.options;
    j["method"] = m.method;
    methods.push_back(j);
  }
  if (s.Measured()) {
    // A cross-validated suite as it was given, with its "cv": parsed again, it expands alike.
    const std::vector<SuiteData>& given_train = s.cv.On() ? s.cv.given_train : s.train_data;
    const std::vector<SuiteData>& given_test = s.cv.On() ? s.cv.given_test : s.test_data;
    nlohmann::json train = nlohmann::json::array(), test = nlohmann::json::array();
    for (const SuiteData& d : given_train) train.push_back(SuiteDataToJson(d));
    for (const SuiteData& d : given_test) test.push_back(SuiteDataToJson(d));
    nlohmann::json data = {{"train", train}};
    if (!given_test.empty()) data["test"] = test;
    nlohmann::json out = {{"name", s.name},     {"vessels", s.vessels}, {"data", data},
                          {"methods", methods}, {"noise", s.noise},     {"seeds", s.seeds}};
    if (s.cv.On()) out["cv"] = s.cv.kind;
    if (!s.pairs.empty()) out["pairs"] = s.pairs;
    return out;
  }
  nlohmann::json out = {{"name", s.name},
                        {"vessels", s.vessels},
                        {"train_maneuvers", s.train_maneuvers},
                        {"test_maneuvers", s.test_maneuvers},
                        {"methods", methods},
                        {"noise", s.noise},
                        {"seeds", s.seeds},
                        {"train_seconds", s.train_seconds},
                        {"test_seconds", s.test_seconds}};
  // Only when given, so that a suite without them echoes (and resumes) as before.
  if (!s.conditions.effects.empty()) out["effects"] = s.conditions.effects;
  if (!s.conditions.sensors.empty()) out["sensors"] = s.conditions.sensors;
  if (!s.conditions.gusts.empty()) out["gusts"] = s.conditions.gusts;
  if (!s.conditions.waves.empty()) out["waves"] = s.conditions.waves;
  if (!s.conditions.dropouts.empty()) out["dropouts"] = s.conditions.dropouts;
  if (!s.conditions.logged.empty()) out["logged"] = s.conditions.logged;
  if (!s.pairs.empty()) out["pairs"] = s.pairs;
  return out;
}

std::vector<FitJob> FitJobs(const Suite& s) {
  // Every method on every training maneuver of every vessel: a method that cannot fit a
  // combination (fossen-ceres models odin3dof only; eb-lr needs steady states and a speed)
  // gives rows saying why, so the tables show the gap instead of hiding it. Only maneuvers a
  // vessel cannot run at all (a zig-zag without a heading) are left out.
  std::vector<FitJob> jobs;
  if (s.Measured()) {
    const std::string vessel = s.vessels.empty() ? "" : s.vessels[0];
    // The data do not change with the seed: only a seeded method's search (gp's) does.
    for (const std::string& train : s.train_maneuvers)
      for (const SuiteMethod& m : s.methods)
        for (double noise : s.noise)
          for (uint64_t seed : s.seeds) {
            jobs.push_back({vessel, train, m, noise, seed});
            if (!FindSuiteMethod(m.method).seeded) break;
          }
    return jobs;
  }
  for (const std::string& vessel : s.vessels) {
    const VesselInfo& info = FindVessel(vessel).Info();
    for (const std::string& train : s.train_maneuvers) {
      if (IsManeuverTest(train) && info.actuation.heading_state < 0) continue;
      if (KindOfManeuver(train) == ManeuverKind::kStepGrid && info.actuation.thrust_input < 0)
        continue;
      for (const SuiteMethod& m : s.methods)
        for (double noise : s.noise)
          for (uint64_t seed : s.seeds) jobs.push_back({vessel, train, m, noise, seed});
    }
  }
  return jobs;
}

}  // namespace usvid
