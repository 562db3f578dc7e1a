#include "harness/suite.h"

#include <filesystem>
#include <set>
#include <sstream>

#include "core/error.h"
#include "simulation/vessel_simulator.h"

namespace usvid {
namespace {

template <typename T>
std::vector<T> ListOf(const nlohmann::json& v, const std::string& where) {
  if (!v.is_array() || v.empty()) throw InputError(where + ": expected a non-empty array");
  std::vector<T> out;
  for (const auto& item : v) {
    try {
      out.push_back(item.get<T>());
    } catch (const nlohmann::json::exception&) {
      throw InputError(where + ": element " + item.dump() + " has the wrong type");
    }
  }
  return out;
}

const std::set<std::string> kMethods = {"gp",    "sindy",   "eb-lr",    "fossen-ceres",
                                        "refit", "nominal", "diagnose", "nomoto"};
constexpr const char* kKnownMethods =
    "gp, sindy, eb-lr, fossen-ceres, refit, nominal, diagnose, nomoto";

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

}  // namespace

std::string SuiteMethod::Label() const {
  if (method == "gp" && options.contains("operators"))
    return "gp[" + options.at("operators").get<std::string>() + "]";
  return method;
}

std::string FitJob::Id() const {
  std::ostringstream s;
  s << vessel << "/" << train_maneuver << "/" << method.Label() << "/noise=" << noise
    << "/seed=" << seed;
  return s.str();
}

Suite ParseSuite(const nlohmann::json& v, const std::string& file) {
  if (!v.is_object()) throw InputError(file + ": a suite is a JSON object");
  static const std::set<std::string> kFields = {
      "name",  "vessels", "train_maneuvers", "test_maneuvers", "methods",
      "noise", "seeds",   "train_seconds",   "test_seconds",   "data"};
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
  if (measured) {
    const nlohmann::json& data = v["data"];
    if (!data.is_object() || !data.contains("train") || !data.contains("test"))
      throw InputError(file + ": data: expected {\"train\": [...], \"test\": [...]}");
    for (const auto& [key, _] : data.items())
      if (key != "train" && key != "test")
        throw InputError(file + ": data: unknown field '" + key + "'");
    for (const char* key : {"train_maneuvers", "test_maneuvers", "train_seconds", "test_seconds"})
      if (v.contains(key))
        throw InputError(file + ": '" + key + "' does not apply to a suite on measured data");
    s.train_data = DataList(data["train"], file, "data: train");
    s.test_data = DataList(data["test"], file, "data: test");
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
  } else {
    s.vessels = ListOf<std::string>(v["vessels"], file + ": vessels");
    s.train_maneuvers = ListOf<std::string>(v["train_maneuvers"], file + ": train_maneuvers");
    s.test_maneuvers = ListOf<std::string>(v["test_maneuvers"], file + ": test_maneuvers");
  }
  for (const std::string& vessel : s.vessels) FindVessel(vessel);  // throws on unknown names
  if (!v["methods"].is_array() || v["methods"].empty())
    throw InputError(file + ": methods: expected a non-empty array");
  for (const auto& m : v["methods"]) {
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
    if (!kMethods.contains(sm.method))
      throw InputError(file + ": methods: unknown method '" + sm.method +
                       "' (known: " + kKnownMethods + ")");
    s.methods.push_back(sm);
  }
  s.noise = v.contains("noise") ? ListOf<double>(v["noise"], file + ": noise")
                                : std::vector<double>{measured ? 0.0 : 0.005};
  for (double n : s.noise)
    if (!(n >= 0 && n < 1)) throw InputError(file + ": noise: levels must be in [0, 1)");
  s.seeds = v.contains("seeds") ? ListOf<uint64_t>(v["seeds"], file + ": seeds")
                                : std::vector<uint64_t>{1};
  for (const char* key : {"train_seconds", "test_seconds"}) {
    if (!v.contains(key)) continue;
    if (!v[key].is_number() || !(v[key].get<double>() > 0))
      throw InputError(file + ": '" + key + "' must be a positive number");
    (std::string(key) == "train_seconds" ? s.train_seconds : s.test_seconds) = v[key].get<double>();
  }
  return s;
}

Suite DefaultSuite(bool quick) {
  const nlohmann::json gp = {{"method", "gp"},
                             {"operators", "+,-,*,abs"},
                             {"population", quick ? 300 : 1000},
                             {"generations", quick ? 10 : 30},
                             {"ols_threshold", 0.001}};
  nlohmann::json suite = {
      {"name", quick ? "default-quick" : "default"},
      {"vessels",
       quick ? nlohmann::json{"odin3dof", "odin-hs"} : nlohmann::json{"odin3dof", "odin-hs"}},
      {"train_maneuvers", {"zigzag:20/20", "stepgrid", "random-steps"}},
      {"test_maneuvers", {"zigzag:20/20", "stepgrid", "random-steps"}},
      // The shooting fit runs at 10 Hz: the 20 Hz step grids of odin-hs are 30k rows.
      {"methods", {gp, "sindy", {{"method", "fossen-ceres"}, {"rate", 10}}, "eb-lr"}},
      {"noise", quick ? nlohmann::json{0.005} : nlohmann::json{0.005, 0.02}},
      {"seeds", quick ? nlohmann::json{1} : nlohmann::json{1, 2, 3}},
      {"train_seconds", quick ? 150 : 300},
      {"test_seconds", quick ? 90 : 180}};
  return ParseSuite(suite, "default suite");
}

nlohmann::json SuiteToJson(const Suite& s) {
  nlohmann::json methods = nlohmann::json::array();
  for (const SuiteMethod& m : s.methods) {
    nlohmann::json j = m.options;
    j["method"] = m.method;
    methods.push_back(j);
  }
  if (s.Measured()) {
    nlohmann::json train = nlohmann::json::array(), test = nlohmann::json::array();
    for (const SuiteData& d : s.train_data) train.push_back(SuiteDataToJson(d));
    for (const SuiteData& d : s.test_data) test.push_back(SuiteDataToJson(d));
    return {
        {"name", s.name},     {"vessels", s.vessels}, {"data", {{"train", train}, {"test", test}}},
        {"methods", methods}, {"noise", s.noise},     {"seeds", s.seeds}};
  }
  return {{"name", s.name},
          {"vessels", s.vessels},
          {"train_maneuvers", s.train_maneuvers},
          {"test_maneuvers", s.test_maneuvers},
          {"methods", methods},
          {"noise", s.noise},
          {"seeds", s.seeds},
          {"train_seconds", s.train_seconds},
          {"test_seconds", s.test_seconds}};
}

std::vector<FitJob> FitJobs(const Suite& s) {
  // Every method on every training maneuver of every vessel: a method that cannot fit a
  // combination (fossen-ceres models odin3dof only; eb-lr needs steady states and a speed)
  // gives rows saying why, so the tables show the gap instead of hiding it. Only maneuvers a
  // vessel cannot run at all (a zig-zag without a heading) are left out.
  std::vector<FitJob> jobs;
  if (s.Measured()) {
    const std::string vessel = s.vessels.empty() ? "" : s.vessels[0];
    // The data do not change with the seed: only the GP search does.
    for (const std::string& train : s.train_maneuvers)
      for (const SuiteMethod& m : s.methods)
        for (double noise : s.noise)
          for (uint64_t seed : s.seeds) {
            jobs.push_back({vessel, train, m, noise, seed});
            if (m.method != "gp") break;
          }
    return jobs;
  }
  for (const std::string& vessel : s.vessels) {
    const VesselInfo& info = FindVessel(vessel).Info();
    for (const std::string& train : s.train_maneuvers) {
      if ((train.starts_with("zigzag") || train.starts_with("turning")) &&
          info.actuation.heading_state < 0)
        continue;
      if (train.starts_with("stepgrid") && info.actuation.thrust_input < 0) continue;
      for (const SuiteMethod& m : s.methods)
        for (double noise : s.noise)
          for (uint64_t seed : s.seeds) jobs.push_back({vessel, train, m, noise, seed});
    }
  }
  return jobs;
}

}  // namespace usvid
