#include "harness/suite_data.h"

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "core/csv_dataset.h"
#include "core/error.h"
#include "core/parse_number.h"
#include "core/records.h"
#include "importers/column_map.h"
#include "importers/csv_log.h"
#include "importers/froude_scaling.h"
#include "importers/hsva_dat.h"
#include "importers/marin_dat.h"
#include "maneuvers/maneuver_spec.h"
#include "preprocessing/heading_rate.h"
#include "preprocessing/record_end.h"

namespace usvid {

std::string SuitePath(const std::string& base_dir, const std::string& file) {
  if (std::filesystem::path(file).is_absolute() || base_dir.empty()) return file;
  return (std::filesystem::path(base_dir) / file).lexically_normal().string();
}

SuiteData ParseSuiteData(const nlohmann::json& v, const std::string& base_dir,
                         const std::string& where) {
  if (!v.is_object()) throw InputError(where + ": each data entry is an object");
  static const std::set<std::string> kFields = {"name",      "file",        "format", "map",
                                                "rate_from", "end_at_stop", "from_s", "to_s",
                                                "maneuver",  "scale"};
  for (const auto& [key, value] : v.items()) {
    if (!kFields.contains(key)) throw InputError(where + ": unknown field '" + key + "'");
    const bool number = key == "from_s" || key == "to_s" || key == "scale";
    if (key == "file" && value.is_array()) {
      if (value.empty() || !std::ranges::all_of(value, [](const auto& f) { return f.is_string(); }))
        throw InputError(where + ": 'file' must be a path or a non-empty list of paths");
      continue;
    }
    if (number ? !value.is_number() : !value.is_string())
      throw InputError(where + ": '" + key + "' must be a " + (number ? "number" : "string"));
  }
  for (const char* required : {"name", "file"})
    if (!v.contains(required)) throw InputError(where + ": missing field '" + required + "'");
  SuiteData d;
  d.name = v["name"].get<std::string>();
  for (const auto& f : v["file"].is_array() ? v["file"] : nlohmann::json::array({v["file"]})) {
    d.files.push_back(SuitePath(base_dir, f.get<std::string>()));
  }
  d.format = v.value("format", d.format);
  if (d.format != "csv" && d.format != "marin-dat" && d.format != "hsva-dat" &&
      d.format != "csv-log")
    throw InputError(where + ": format '" + d.format +
                     "' (known: csv, marin-dat, hsva-dat, csv-log)");
  d.map = v.value("map", std::string());
  if (!d.map.empty() && d.format != "csv-log")
    throw InputError(where + ": 'map' applies to format csv-log only");
  d.rate_from = v.value("rate_from", std::string());
  d.end_at_stop = v.value("end_at_stop", std::string());
  d.maneuver = v.value("maneuver", std::string());
  if (!d.maneuver.empty() && !IsManeuverTest(d.maneuver))
    throw InputError(
        where + ": maneuver '" + d.maneuver +
        "': only a zig-zag or a turning circle can be replayed (zigzag:A/B, turning:A)");
  d.from_s = v.value("from_s", d.from_s);
  d.to_s = v.value("to_s", d.to_s);
  if (!(d.from_s < d.to_s)) throw InputError(where + ": from_s must be before to_s");
  d.scale = v.value("scale", d.scale);
  if (!(std::isfinite(d.scale) && d.scale > 0))
    throw InputError(where +
                     ": 'scale' must be a Froude scale lambda > 0 (L_target / L_log), not " +
                     FormatNumber(d.scale));
  return d;
}

nlohmann::json SuiteDataToJson(const SuiteData& d) {
  nlohmann::json j = {
      {"name", d.name},
      {"file", d.files.size() == 1 ? nlohmann::json(d.files.front()) : nlohmann::json(d.files)},
      {"format", d.format}};
  if (!d.map.empty()) j["map"] = d.map;
  if (!d.rate_from.empty()) j["rate_from"] = d.rate_from;
  if (!d.end_at_stop.empty()) j["end_at_stop"] = d.end_at_stop;
  if (!d.maneuver.empty()) j["maneuver"] = d.maneuver;
  if (std::isfinite(d.from_s)) j["from_s"] = d.from_s;
  if (std::isfinite(d.to_s)) j["to_s"] = d.to_s;
  if (d.scale != 1.0) j["scale"] = d.scale;
  return j;
}

namespace {

// One file of the entry, read and cut as the entry says.
Dataset LoadRecord(const SuiteData& d, const std::string& file) {
  ImportReport report;
  Dataset data;
  if (d.format == "marin-dat") {
    data = ImportMarinDat(file, report);
  } else if (d.format == "hsva-dat") {
    data = ImportHsvaDat(file, report);
  } else if (d.format == "csv-log") {
    std::vector<std::string> items;
    std::stringstream s(d.map);
    for (std::string item; std::getline(s, item, ',');) items.push_back(item);
    data = ImportCsvLog(file, ParseColumnMap(items), report);
  } else {
    data = ReadDatasetCsv(file);
  }
  if (!d.end_at_stop.empty()) EndAtStop(data, d.end_at_stop);
  if (!d.rate_from.empty()) data.Set("r", RateFromHeading(data, d.rate_from));
  if (d.scale != 1.0) {
    try {
      FroudeScale(data, d.scale);
    } catch (const InputError& e) {
      throw InputError(file + ": 'scale': " + e.what());
    }
  }
  if (std::isfinite(d.from_s) || std::isfinite(d.to_s)) {
    std::vector<bool> keep(data.rows());
    for (Eigen::Index k = 0; k < data.rows(); ++k)
      keep[k] = data.t()(k) >= d.from_s && data.t()(k) < d.to_s;
    data.KeepRows(keep);
    if (data.rows() < 4)
      throw InputError(file + ": fewer than 4 rows in [" + std::to_string(d.from_s) + ", " +
                       std::to_string(d.to_s) + ") s");
  }
  return data;
}

}  // namespace

Dataset LoadSuiteData(const SuiteData& d) {
  std::vector<Dataset> records;
  for (const std::string& file : d.files) records.push_back(LoadRecord(d, file));
  return JoinRecords(std::move(records));
}

}  // namespace usvid
