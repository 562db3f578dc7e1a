#include "harness/track_file.h"

#include <algorithm>
#include <filesystem>
#include <set>

#include "core/error.h"
#include "core/yaml_section.h"
#include "importers/column_map.h"
#include "importers/csv_log.h"
#include "methods/fossen_ceres/fossen_fit.h"
#include "methods/gp/gp_identify.h"
#include "methods/nominal/nominal.h"
#include "methods/nomoto/nomoto.h"
#include "methods/refit/refit.h"
#include "methods/sindy/sindy.h"

namespace usvid {
namespace {

namespace fs = std::filesystem;

// The channels a log's column may be mapped to (docs/data.md#channels): states, derived states,
// earth-fixed velocities (turned to body axes), inputs and the wind.
const std::set<std::string>& KnownChannels() {
  // clang-format off
  static const std::set<std::string> known = {
      "t", "north", "east", "psi", "u", "v", "r", "U", "chi", "vn", "ve", "phi",
      "delta", "n", "rev", "rpm", "throttle", "nozzle", "bucket", "tau_x", "tau_y", "tau_n",
      "wind_speed", "wind_direction", "wind_speed_true", "wind_direction_true"};
  // clang-format on
  return known;
}

std::string Joined(const std::set<std::string>& items) {
  std::string out;
  for (const std::string& s : items) out += (out.empty() ? "" : ", ") + s;
  return out;
}

// A YAML value as JSON: a mapping and a list as such, a scalar as a number or true/false when it
// reads as one, else as text (a method's options, as a suite file gives them).
nlohmann::json ToJson(const YAML::Node& node) {
  if (node.IsMap()) {
    nlohmann::json out = nlohmann::json::object();
    for (const auto& kv : node) out[kv.first.Scalar()] = ToJson(kv.second);
    return out;
  }
  if (node.IsSequence()) {
    nlohmann::json out = nlohmann::json::array();
    for (const YAML::Node& item : node) out.push_back(ToJson(item));
    return out;
  }
  if (!node.IsScalar()) return nullptr;
  const std::string& s = node.Scalar();
  if (node.Tag() != "!") {  // not quoted
    long long i = 0;
    double x = 0.0;
    if (YAML::convert<long long>::decode(node, i)) return i;
    if (YAML::convert<double>::decode(node, x)) return x;
    // true and false alone: YAML 1.1's y, n, on, off are channel names here (inputs: [n, delta]).
    if (s == "true" || s == "false") return s == "true";
  }
  return s;
}

// The columns: usvid's channel -> the log's column[:unit], as `usvid import --map`.
void ReadColumns(YamlSection& top, TrackFile& track) {
  std::optional<YamlSection> columns = top.Child("columns");
  const std::string format = track.read.value("format", "csv-log");
  if (!columns) {
    if (format == "csv-log")
      top.FailHere("columns: missing (the log's column of each channel, at least t)");
    return;
  }
  if (format != "csv-log")
    top.FailKey("columns", "format " + format + " names its own columns; columns is for csv-log");
  std::string map;
  for (const auto& [target, value] : columns->Items()) {
    if (!KnownChannels().contains(target))
      columns->Fail(value, target + ": unknown channel (known: " + Joined(KnownChannels()) + ")");
    if (!value.IsScalar() || value.Scalar().empty())
      columns->Fail(value, target + ": expected the log's column name");
    if (value.Scalar().find(',') != std::string::npos)
      columns->Fail(value, target + ": a column name with a comma cannot be mapped");
    std::string source;
    try {  // the column and its unit, as `usvid import --map` reads them
      source = ParseColumnMap({target + "=" + value.Scalar()}).at(0).source;
    } catch (const InputError& e) {
      columns->Fail(value, target + ": " + e.what());
    }
    const YAML::Mark m = value.Mark();
    track.columns.push_back({target, source, m.line + 1, m.column + 1});
    map += (map.empty() ? "" : ",") + target + "=" + value.Scalar();
  }
  if (std::none_of(track.columns.begin(), track.columns.end(),
                   [](const TrackColumn& c) { return c.target == "t"; }))
    columns->FailHere("t: missing (the log's time column)");
  track.read["map"] = map;
}

void ReadFolders(YamlSection& top, TrackFile& track) {
  std::optional<YamlSection> runs = top.Child("runs");
  if (!runs) return;
  static const std::set<std::string> kTests = {"zigzag", "turning", "any", "none"};
  for (const auto& [path, value] : runs->Items()) {
    if (!value.IsScalar() || !kTests.contains(value.Scalar()))
      runs->Fail(value, path + ": the tests its runs hold: " + Joined(kTests));
    if (track.check_runs && !fs::is_directory(fs::path(track.folder) / path))
      runs->Fail(value, path + ": no such subfolder of " + track.folder);
    track.folders.push_back({path, value.Scalar() == "none" ? "" : value.Scalar()});
  }
}

// A split's entry: a file, or {file, name, maneuver, from_s, to_s}, read as every run is.
nlohmann::json SplitEntry(const YamlSection& split, const YAML::Node& item, const TrackFile& track,
                          const std::string& part) {
  nlohmann::json entry = track.read;
  if (item.IsScalar()) {
    entry["file"] = item.Scalar();
  } else {
    YamlSection s(split.file(), item, split.path() + part + ".");
    const std::optional<std::string> file = s.Text("file");
    if (!file) s.FailHere("file: missing (the run's file, from the vessel folder)");
    entry["file"] = *file;
    if (const auto name = s.Text("name")) entry["name"] = *name;
    if (const auto maneuver = s.Text("maneuver")) entry["maneuver"] = *maneuver;
    if (const auto from = s.Number("from_s")) entry["from_s"] = *from;
    if (const auto to = s.Number("to_s")) entry["to_s"] = *to;
    // The track's way of reading, overridden for this run: "none" for no end.
    for (const char* key : {"end_at_stop", "rate_from"})
      if (const auto v = s.Text(key)) {
        if (*v == "none")
          entry.erase(key);
        else
          entry[key] = *v;
      }
    s.RefuseUnknown();
  }
  const std::string file = entry["file"].get<std::string>();
  if (track.check_runs && !fs::is_regular_file(fs::path(track.folder) / file))
    split.Fail(item, part + ": " + file + ": no such run in " + track.folder);
  if (!entry.contains("name")) entry["name"] = fs::path(file).stem().string();
  return entry;
}

void ReadSplit(YamlSection& top, TrackFile& track) {
  std::optional<YamlSection> split = top.Child("split");
  if (!split) return;
  track.split = true;
  for (const char* part : {"train", "test"}) {
    const YAML::Node list = split->Node(part);
    if (!list.IsDefined() || !list.IsSequence() || list.size() == 0)
      split->FailHere(std::string(part) + ": expected a list of runs");
    for (const YAML::Node& item : list)
      (std::string(part) == "train" ? track.train : track.test)
          .push_back(SplitEntry(*split, item, track, part));
  }
  split->RefuseUnknown();
}

}  // namespace

nlohmann::json DefaultTrackMethods(bool has_vessel, const std::set<std::string>& channels) {
  nlohmann::json out = nlohmann::json::array();
  if (has_vessel) {
    out.push_back(std::string(kNominalMethodName));
    out.push_back(std::string(kRefitMethodName));
    out.push_back(std::string(fossen::kMethodName));
    out.push_back(std::string(nomoto::kMethodName));
  } else if (channels.contains("r") && channels.contains("delta")) {
    out.push_back(
        {{"method", std::string(nomoto::kMethodName)}, {"states", {"r"}}, {"inputs", {"delta"}}});
  }
  out.push_back(std::string(sindy::kMethodName));
  out.push_back(std::string(gp::kMethodName));
  if (has_vessel) out.push_back({{"method", std::string(gp::kMethodName)}, {"base", "vessel"}});
  return out;
}

std::vector<std::string> RunExtensions(const std::string& format) {
  if (format == "marin-dat" || format == "hsva-dat") return {".dat"};
  return {".csv"};
}

namespace {

TrackFile ParseTrack(const YAML::Node& root, TrackFile track) {
  const std::string& path = track.file;
  YamlSection top(path, root, "");
  track.name = top.Text("name").value_or(fs::absolute(track.folder).lexically_normal().filename());
  if (track.name.empty()) track.name = fs::absolute(track.folder).parent_path().filename();
  if (const std::optional<std::string> vessel = top.Text("vessel")) {
    const fs::path file = fs::path(track.folder) / *vessel;
    track.vessel = fs::is_regular_file(file) ? file.string() : *vessel;
  } else if (fs::is_regular_file(fs::path(track.folder) / "vessel.yaml")) {
    track.vessel = (fs::path(track.folder) / "vessel.yaml").string();
  }
  const std::string format = top.Text("format").value_or("csv-log");
  static const std::set<std::string> kFormats = {"csv", "csv-log", "hsva-dat", "marin-dat"};
  if (!kFormats.contains(format))
    top.FailKey("format", "'" + format + "' (known: " + Joined(kFormats) + ")");
  track.read = {{"format", format}};
  ReadColumns(top, track);
  for (const char* key : {"rate_from", "end_at_stop"})
    if (const std::optional<std::string> v = top.Text(key)) track.read[key] = *v;
  if (top.Number("scale")) track.read["scale"] = top.Positive("scale", "the Froude scale");
  if (std::optional<YamlSection> also = top.Child("also")) {
    static const std::set<std::string> kNamed = {"csv", "hsva-dat", "marin-dat"};
    for (const auto& [extension, value] : also->Items()) {
      if (!extension.starts_with(".") || extension.size() < 2)
        also->Fail(value, extension + ": expected a file extension (.csv)");
      if (!value.IsScalar() || !kNamed.contains(value.Scalar()))
        also->Fail(value, extension + ": the format its files are read in: " + Joined(kNamed));
      track.also.emplace_back(extension, value.Scalar());
    }
  }
  ReadFolders(top, track);
  ReadSplit(top, track);
  const YAML::Node methods = top.Node("methods");
  if (methods.IsDefined()) {
    if (!methods.IsSequence() || methods.size() == 0)
      top.FailKey("methods", "expected a list of methods, each a name or {method: NAME, ...}");
    track.methods = ToJson(methods);
  } else {
    std::set<std::string> channels;
    for (const TrackColumn& c : track.columns) channels.insert(c.target);
    if (track.read.contains("rate_from")) channels.insert("r");
    if (track.columns.empty()) channels = KnownChannels();  // a format that names its own
    track.methods = DefaultTrackMethods(!track.vessel.empty(), channels);
  }
  top.RefuseUnknown();
  return track;
}

}  // namespace

TrackFile ReadTrackFile(const std::string& path) {
  TrackFile track;
  track.file = path;
  track.folder = fs::path(path).parent_path().string();
  if (track.folder.empty()) track.folder = ".";
  return ParseTrack(LoadYamlFile(path, "track file"), std::move(track));
}

TrackFile ReadBuiltInTrack(const std::string& text, const std::string& label,
                           const std::string& folder) {
  TrackFile track;
  track.file = label;
  track.folder = folder;
  track.check_runs = false;
  return ParseTrack(LoadYamlText(text, label), std::move(track));
}

void CheckColumnsOf(const TrackFile& track, const std::string& run) {
  if (track.columns.empty()) return;
  const std::vector<std::string> header = CsvLogColumns(run);
  const std::set<std::string> have(header.begin(), header.end());
  for (const TrackColumn& c : track.columns)
    if (!have.contains(c.source))
      throw InputError(
          Located(track.file, c.line, c.column,
                  "columns." + c.target + ": '" + c.source + "' is not a column of " + run));
}

}  // namespace usvid
