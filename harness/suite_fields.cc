#include "harness/suite_fields.h"

#include <algorithm>
#include <array>
#include <filesystem>
#include <sstream>
#include <type_traits>

#include "core/error.h"
#include "harness/cross_validation.h"
#include "harness/suite.h"
#include "maneuvers/maneuver_factory.h"
#include "simulation/vessel_simulator.h"

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

using Context = SuiteFieldContext;

std::string Text(const nlohmann::json& v, const Context& c, const std::string& form) {
  if (!v.is_string()) throw InputError(c.file + ": '" + c.key + "' must be a string" + form);
  return v.get<std::string>();
}

// A maneuver must run on at least one of the suite's vessels (a zig-zag needs a heading, which
// not every vessel has): refused before any fit.
void CheckManeuver(const Suite& s, const std::string& spec, const std::string& where) {
  std::string why;
  for (const VesselRef& vessel : s.vessels) {
    try {
      MakeManeuver(spec, vessel.Info().actuation, 0.0, 1);
      return;
    } catch (const InputError& e) {
      if (why.empty()) why = e.what();
    }
  }
  if (!why.empty()) throw InputError(where + ": " + why);
}

void ReadName(const nlohmann::json& v, const Context& c, Suite& s) { s.name = Text(v, c, ""); }

// Expanded with the data (ReadData), which it needs.
void ReadCv(const nlohmann::json& v, const Context& c, Suite& s) {
  s.cv.kind = Text(v, c, std::string(" (\"") + kCrossValidationRuns + "\")");
}

// A simulated suite's vessels, or a measured one's (at most one, or none when the methods name
// their channels); a vessel file named relative to the suite, as its data are.
void ReadVessels(const nlohmann::json& v, const Context& c, Suite& s) {
  std::vector<std::string> names;
  if (c.measured) {
    if (!v.is_array()) throw InputError(c.file + ": vessels: expected an array");
    for (const auto& item : v) {
      if (!item.is_string()) throw InputError(c.file + ": vessels: names are strings");
      names.push_back(item.get<std::string>());
    }
    if (names.size() > 1)
      throw InputError(c.file + ": a suite on measured data has at most one vessel");
  } else {
    names = ListOf<std::string>(v, c.file + ": vessels");
  }
  s.vessels.clear();
  for (std::string& name : names) {
    if (IsVesselFile(name))
      name = SuitePath(std::filesystem::path(c.file).parent_path().string(), name);
    s.vessels.emplace_back(name);  // resolved here: throws on an unknown name
  }
}

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

// The training and test files; a cross-validated suite (`cv`) may leave out "test": every run
// is held out in turn (harness/cross_validation.h).
void ReadData(const nlohmann::json& data, const Context& c, Suite& s) {
  const std::string& file = c.file;
  if (!data.is_object() || !data.contains("train") || (!s.cv.On() && !data.contains("test")))
    throw InputError(file + ": data: expected {\"train\": [...], \"test\": [...]}");
  for (const auto& [key, _] : data.items())
    if (key != "train" && key != "test")
      throw InputError(file + ": data: unknown field '" + key + "'");
  s.train_data = DataList(data["train"], file, "data: train");
  if (data.contains("test")) s.test_data = DataList(data["test"], file, "data: test");
  for (const SuiteData& d : s.test_data)
    if (d.files.size() > 1)  // a test is one free run, which no gap may cut
      throw InputError(file + ": data: test: '" + d.name +
                       "': a test entry is one file (a list of files joins records for training)");
  for (const SuiteData& d : s.train_data) s.train_maneuvers.push_back(d.name);
  for (const SuiteData& d : s.test_data) s.test_maneuvers.push_back(d.name);
  if (s.cv.On()) ExpandCrossValidation(s, s.cv.kind, file);
  for (const SuiteData& d : s.test_data)
    if (!d.maneuver.empty()) CheckManeuver(s, d.maneuver, file + ": data: test: " + d.name);
}

template <std::vector<std::string> Suite::*kManeuvers>
void ReadManeuvers(const nlohmann::json& v, const Context& c, Suite& s) {
  s.*kManeuvers = ListOf<std::string>(v, c.file + ": " + c.key);
  for (const std::string& m : s.*kManeuvers) CheckManeuver(s, m, c.file + ": " + c.key);
}

// The methods: names, or objects with "method" and its options.
void ReadMethods(const nlohmann::json& list, const Context& c, Suite& s) {
  if (!list.is_array() || list.empty())
    throw InputError(c.file + ": methods: expected a non-empty array");
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
      throw InputError(c.file + ": methods: each is a name or an object with \"method\"");
    }
    try {
      FindSuiteMethod(sm.method);
    } catch (const InputError& e) {
      throw InputError(c.file + ": methods: " + e.what());
    }
    CheckSuiteMethod(sm, c.file + ": methods");
    s.methods.push_back(sm);
  }
}

// Two method names each, each a method of the suite, the two different.
void ReadPairs(const nlohmann::json& v, const Context& c, Suite& s) {
  const std::string what = c.file + ": pairs: ";
  if (!v.is_array()) throw InputError(what + "must be a list of pairs of method names");
  for (const nlohmann::json& p : v) {
    if (!p.is_array() || p.size() != 2 || !p[0].is_string() || !p[1].is_string())
      throw InputError(what + "each pair is two method names, as [\"gp\", \"eb-lr\"], got " +
                       p.dump());
    std::array<std::string, 2> pair{p[0].get<std::string>(), p[1].get<std::string>()};
    if (pair[0] == pair[1]) throw InputError(what + "a pair of '" + pair[0] + "' with itself");
    for (const std::string& name : pair)
      if (std::ranges::none_of(s.methods, [&](const SuiteMethod& m) { return m.method == name; }))
        throw InputError(what + "'" + name + "' is not among the suite's methods");
    s.pairs.push_back(pair);
  }
}

void ReadNoise(const nlohmann::json& v, const Context& c, Suite& s) {
  s.noise = ListOf<double>(v, c.file + ": noise");
  for (double n : s.noise)
    if (!(n >= 0 && n < 1)) throw InputError(c.file + ": noise: levels must be in [0, 1)");
}

void ReadSeeds(const nlohmann::json& v, const Context& c, Suite& s) {
  s.seeds = ListOf<uint64_t>(v, c.file + ": seeds");
}

// A condition's items, read alone: checked against each other and the vessels once all are
// read (CheckSuiteConditions, harness/suite.h).
template <std::vector<std::string> SuiteConditions::*kItems>
void ReadItems(const nlohmann::json& v, const Context& c, Suite& s) {
  s.conditions.*kItems = ListOf<std::string>(v, c.file + ": " + c.key);
}

template <std::string SuiteConditions::*kText>
void ReadConditionText(const nlohmann::json& v, const Context& c, Suite& s) {
  const std::string form =
      kText == &SuiteConditions::gusts ? ", SPEED[:FROM_DEG]" : ", HS[:TP[:FROM_DEG]]";
  s.conditions.*kText = Text(v, c, form);
}

template <double Suite::*kSeconds>
void ReadSeconds(const nlohmann::json& v, const Context& c, Suite& s) {
  if (!v.is_number() || !(v.get<double>() > 0))
    throw InputError(c.file + ": '" + c.key + "' must be a positive number");
  s.*kSeconds = v.get<double>();
}

using Json = nlohmann::json;

Json WriteName(const Suite& s) { return s.name; }
Json WriteCv(const Suite& s) { return s.cv.On() ? Json(s.cv.kind) : Json(); }
Json WriteVessels(const Suite& s) {
  Json names = Json::array();
  for (const VesselRef& vessel : s.vessels) names.push_back(vessel.Name());
  return names;
}

// A cross-validated suite as it was given, with its "cv": parsed again, it expands alike.
Json WriteData(const Suite& s) {
  const std::vector<SuiteData>& given_train = s.cv.On() ? s.cv.given_train : s.train_data;
  const std::vector<SuiteData>& given_test = s.cv.On() ? s.cv.given_test : s.test_data;
  Json train = Json::array(), test = Json::array();
  for (const SuiteData& d : given_train) train.push_back(SuiteDataToJson(d));
  for (const SuiteData& d : given_test) test.push_back(SuiteDataToJson(d));
  Json data = {{"train", train}};
  if (!given_test.empty()) data["test"] = test;
  return data;
}

template <std::vector<std::string> Suite::*kManeuvers>
Json WriteManeuvers(const Suite& s) {
  return s.*kManeuvers;
}

Json WriteMethods(const Suite& s) {
  Json methods = Json::array();
  for (const SuiteMethod& m : s.methods) {
    Json j = m.options;
    j["method"] = m.method;
    methods.push_back(j);
  }
  return methods;
}

Json WritePairs(const Suite& s) { return s.pairs.empty() ? Json() : Json(s.pairs); }
Json WriteNoise(const Suite& s) { return s.noise; }
Json WriteSeeds(const Suite& s) { return s.seeds; }

template <std::vector<std::string> SuiteConditions::*kItems>
Json WriteItems(const Suite& s) {
  const std::vector<std::string>& items = s.conditions.*kItems;
  return items.empty() ? Json() : Json(items);
}

template <std::string SuiteConditions::*kText>
Json WriteConditionText(const Suite& s) {
  const std::string& text = s.conditions.*kText;
  return text.empty() ? Json() : Json(text);
}

template <double Suite::*kSeconds>
Json WriteSeconds(const Suite& s) {
  return s.*kSeconds;
}

const char* KindName(SuiteKind kind) {
  return kind == SuiteKind::kAny         ? "every"
         : kind == SuiteKind::kSimulated ? "simulated"
                                         : "measured";
}

constexpr char kMeasuredHaveTheirOwn[] = "makes simulated records; measured data have their own";

}  // namespace

const std::vector<SuiteField>& SuiteFields() {
  using K = SuiteKind;
  constexpr std::string_view kNotMeasured = "does not apply to a suite on measured data";
  static const std::vector<SuiteField> fields = {
      {"name", K::kAny, K::kNone, "\"suite\"",
       "the suite's name: the output's title and its cells' suite", "", ReadName, WriteName},
      {"cv", K::kMeasured, K::kNone, "none",
       "\"runs\": leave-one-run-out cross-validation, each run held out in turn "
       "(docs/compare.md#cross-validation-over-runs; `usvid compare --cv runs`)",
       "cv: a simulated suite has no runs to leave out (cv needs a suite on measured data, "
       "\"data\": {...})",
       ReadCv, WriteCv},
      {"vessels", K::kAny, K::kSimulated,
       "none (on measured data whose methods name their channels)",
       "compiled-in vessel names or vessel files (docs/model.md#vessel-files), a file named "
       "relative to the suite; at most one on measured data",
       "", ReadVessels, WriteVessels},
      {"data", K::kMeasured, K::kMeasured, "",
       "{\"train\": [entries], \"test\": [entries]}: the measured records (harness/suite_data.h); "
       "a training entry's \"file\" may be a list, jointly fitted",
       "", ReadData, WriteData},
      {"train_maneuvers", K::kSimulated, K::kSimulated, "",
       "maneuver specs simulated for training (docs/data.md#maneuvers)", kNotMeasured,
       ReadManeuvers<&Suite::train_maneuvers>, WriteManeuvers<&Suite::train_maneuvers>},
      {"test_maneuvers", K::kSimulated, K::kSimulated, "",
       "maneuver specs simulated for the held-out scores, each with the training seed + 1000",
       kNotMeasured, ReadManeuvers<&Suite::test_maneuvers>, WriteManeuvers<&Suite::test_maneuvers>},
      {"methods", K::kAny, K::kAny, "",
       "method names, or {\"method\": NAME, options...} (docs/options.md, and the keys every "
       "method shares)",
       "", ReadMethods, WriteMethods},
      {"pairs", K::kAny, K::kNone, "none",
       "[[A, B], ...]: pairs of the suite's methods the verdict tests head to head on every table",
       "", ReadPairs, WritePairs},
      {"noise", K::kAny, K::kNone, "[0.005] simulated, [0] measured",
       "measurement noise levels, each a share of each channel's standard deviation, in [0, 1)", "",
       ReadNoise, WriteNoise},
      {"seeds", K::kAny, K::kNone, "[1]", "seeds of the simulated records and of the methods", "",
       ReadSeeds, WriteSeeds},
      {"effects", K::kSimulated, K::kNone, "none",
       "effects hidden in the plant, as `usvid simulate --effect` takes them "
       "(docs/data.md#effects)",
       kMeasuredHaveTheirOwn, ReadItems<&SuiteConditions::effects>,
       WriteItems<&SuiteConditions::effects>},
      {"sensors", K::kSimulated, K::kNone, "none",
       "sensors sampled slower than the output, as `usvid simulate --rates` takes them (imu=50, "
       "gps=5)",
       kMeasuredHaveTheirOwn, ReadItems<&SuiteConditions::sensors>,
       WriteItems<&SuiteConditions::sensors>},
      {"gusts", K::kSimulated, K::kNone, "none",
       "a gusty wind, SPEED[:FROM_DEG], as `usvid simulate --gusts`", kMeasuredHaveTheirOwn,
       ReadConditionText<&SuiteConditions::gusts>, WriteConditionText<&SuiteConditions::gusts>},
      {"waves", K::kSimulated, K::kNone, "none (calm)",
       "the waves' first-order motion, HS[:TP[:FROM_DEG]], as `usvid simulate --waves`",
       kMeasuredHaveTheirOwn, ReadConditionText<&SuiteConditions::waves>,
       WriteConditionText<&SuiteConditions::waves>},
      {"dropouts", K::kSimulated, K::kNone, "none",
       "sensor dropouts, as `usvid simulate --dropouts` takes them", kMeasuredHaveTheirOwn,
       ReadItems<&SuiteConditions::dropouts>, WriteItems<&SuiteConditions::dropouts>},
      {"logged", K::kSimulated, K::kNone, "none",
       "disturbances the records log and the equation methods read as inputs (wind, current), "
       "as `usvid simulate --logged`",
       kMeasuredHaveTheirOwn, ReadItems<&SuiteConditions::logged>,
       WriteItems<&SuiteConditions::logged>},
      {"train_seconds", K::kSimulated, K::kNone, "300", "seconds of each training record",
       kNotMeasured, ReadSeconds<&Suite::train_seconds>, WriteSeconds<&Suite::train_seconds>},
      {"test_seconds", K::kSimulated, K::kNone, "180", "seconds of each test record", kNotMeasured,
       ReadSeconds<&Suite::test_seconds>, WriteSeconds<&Suite::test_seconds>},
  };
  return fields;
}

std::string SuiteFieldsMarkdown() {
  std::ostringstream md;
  md << "# Suite files\n\n"
     << "Generated by `usvid compare --fields` from the one declaration of a suite's fields "
        "(harness/suite_fields.h); do not edit by hand. A suite is a JSON object (`//` and "
        "`/* */` comments allowed) of these fields, read in this order; an unknown field, a "
        "field of the other kind of suite, a missing required one or a value of the wrong type "
        "is an error naming the file and the field, exit 2 ([compare.md](compare.md)). A suite "
        "with `data` is on measured data; one without simulates its records.\n\n"
     << "| field | suites | default | what |\n| --- | --- | --- | --- |\n";
  for (const SuiteField& f : SuiteFields()) {
    const std::string given = f.required == SuiteKind::kNone ? std::string(f.default_text)
                              : f.required == f.applies
                                  ? std::string("required")
                                  : "required in a " + std::string(KindName(f.required)) +
                                        " suite; else " + std::string(f.default_text);
    md << "| `" << f.key << "` | " << KindName(f.applies) << " | " << given << " | " << f.what
       << " |\n";
  }
  return md.str();
}

}  // namespace usvid
