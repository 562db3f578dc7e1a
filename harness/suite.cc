#include "harness/suite.h"

#include <algorithm>
#include <optional>
#include <sstream>

#include "core/error.h"
#include "effects/effect.h"
#include "effects/effect_values.h"
#include "harness/suite_fields.h"
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
  s << vessel.Name() << "/" << train_maneuver << "/" << method.Label() << "/noise=" << noise
    << "/seed=" << seed;
  return s.str();
}

void CheckSuiteConditions(const Suite& s, const std::string& file) {
  if (s.conditions.empty()) return;
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
  for (const VesselRef& vessel : s.vessels) {
    const VesselInfo& info = vessel.Info();
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

Suite ParseSuite(const nlohmann::json& v, const std::string& file) {
  if (!v.is_object()) throw InputError(file + ": a suite is a JSON object");
  const bool measured = v.contains("data");
  const std::vector<SuiteField>& fields = SuiteFields();
  auto field = [&](const std::string& key) {
    return std::ranges::find_if(fields, [&](const SuiteField& f) { return f.key == key; });
  };
  // Every key known and given to a suite it applies to, every required one given, before any
  // is read.
  for (const auto& [key, _] : v.items()) {
    const auto f = field(key);
    if (f == fields.end()) throw InputError(file + ": unknown field '" + key + "'");
    if (!f->AppliesTo(measured)) {
      const std::string said(f->elsewhere);
      throw InputError(file + ": " +
                       (said.starts_with(key + ":") ? said : "'" + key + "' " + said));
    }
  }
  for (const SuiteField& f : fields)
    if (f.RequiredIn(measured) && !v.contains(f.key))
      throw InputError(file + ": missing field '" + std::string(f.key) + "'");
  Suite s;
  s.noise = {measured ? 0.0 : 0.005};
  s.seeds = {1};
  for (const SuiteField& f : fields)
    if (v.contains(f.key)) f.read(v[f.key], {file, std::string(f.key), measured}, s);
  CheckSuiteConditions(s, file);
  return s;
}

nlohmann::json SuiteToJson(const Suite& s) {
  nlohmann::json out = nlohmann::json::object();
  for (const SuiteField& f : SuiteFields()) {
    if (!f.AppliesTo(s.Measured())) continue;
    nlohmann::json value = f.write(s);
    if (!value.is_null()) out[std::string(f.key)] = std::move(value);
  }
  return out;
}

std::vector<FitJob> FitJobs(const Suite& s) {
  // Every method on every training maneuver of every vessel: a method that cannot fit a
  // combination (fossen-ceres models odin3dof only; eb-lr needs steady states and a speed)
  // gives rows saying why, so the tables show the gap instead of hiding it. Only maneuvers a
  // vessel cannot run at all (a zig-zag without a heading) are left out.
  std::vector<FitJob> jobs;
  if (s.Measured()) {
    const VesselRef vessel = s.vessels.empty() ? VesselRef() : s.vessels[0];
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
  for (const VesselRef& vessel : s.vessels) {
    const VesselInfo& info = vessel.Info();
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
