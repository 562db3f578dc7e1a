// Measured data in a comparison suite: instead of simulated maneuvers, a suite may train and
// test on recorded files ("data": {"train": [...], "test": [...]}), each
//   {"name": "zigzag 20/-20", "file": "path",
//    "format": "csv" | "marin-dat" | "hsva-dat" | "csv-log",
//    "map": "t=time,psi=psi,delta=delta" (csv-log: import --map), "rate_from": "psi",
//    "end_at_stop": "n", "scale": 45.7,
//    "from_s": 0, "to_s": 140, "maneuver": "zigzag:-20/20"}
// "file" may be a list of paths: the records, each read and cut alike, are joined for one
// joint fit (core/records.h; a training entry only). Paths are relative to the suite file's
// folder. "rate_from" adds the rate of turn r from that
// heading (preprocessing/heading_rate.h) for logs without a gyro. "end_at_stop" ends each
// record at the last row where that actuator still runs, as `usvid import --end-at-stop`
// (preprocessing/record_end.h: the recovery after a test). "scale" Froude-scales each record by
// lambda (> 0, default 1), as `usvid import --scale` (importers/froude_scaling.h), after the
// end and the rate and before the cut. A file is read as `usvid import` would read it, with the
// same repairs; a csv file's F.record.json and an hsva-dat file's header give the record's
// metadata "maneuver", the log's own words (a joined list of files has none). "from_s" and
// "to_s" keep the rows with from_s <= t < to_s, t after the scaling (a held-back part of one log
// as its own test set). The entry's "maneuver" names the maneuver a test record was run with
// (maneuver_factory.h: zigzag:A/B or turning:A, A in starboard-positive degrees; zigzag or
// turning alone: read from the record, metrics/maneuver_of_record.h), so that compare can replay
// it closed-loop on each model; without it the record is scored on its recorded inputs only.
#pragma once

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/dataset.h"

namespace usvid {

struct SuiteData {
  std::string name, format = "csv", map, rate_from, end_at_stop, maneuver;
  std::vector<std::string> files;  // one, or several records joined
  double from_s = -INFINITY, to_s = INFINITY;
  double scale = 1.0;  // Froude scale lambda, as `usvid import --scale`
};

// Throws InputError naming `where` for a malformed entry.
// `file` taken from `base_dir` when it is relative (a suite's data and vessel files).
std::string SuitePath(const std::string& base_dir, const std::string& file);

SuiteData ParseSuiteData(const nlohmann::json& value, const std::string& base_dir,
                         const std::string& where);
nlohmann::json SuiteDataToJson(const SuiteData& d);

// Throws InputError for an unreadable or malformed file.
Dataset LoadSuiteData(const SuiteData& d);

}  // namespace usvid
