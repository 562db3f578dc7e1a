// usvid import --format marin-dat|hsva-dat|csv --data LOG [--map NEW=OLD[:unit],...]
//   [--end-at-stop CH] [--scale LAMBDA]
//   --out F.csv     (and F.record.json beside it when the log names its maneuver)

#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>

#include "apps/usvid/commands.h"
#include "core/atomic_file.h"
#include "core/csv_dataset.h"
#include "core/error.h"
#include "core/json_file.h"
#include "importers/csv_log.h"
#include "importers/froude_scaling.h"
#include "importers/hsva_dat.h"
#include "importers/marin_dat.h"
#include "preprocessing/heading_rate.h"
#include "preprocessing/rate_calibration.h"
#include "preprocessing/record_end.h"

namespace usvid {
namespace {

struct ImportOptions {
  std::string format;
  std::string data;
  std::vector<std::string> map;
  std::string rate_from;
  std::string rate_bias_from;
  std::string end_at_stop;
  double scale = 1.0;
  std::vector<std::string> dimensions;
  std::string out;
};

// --dimension NAME=KIND,...
std::map<std::string, Dimension> ParseDimensions(const std::vector<std::string>& items) {
  std::map<std::string, Dimension> out;
  for (const std::string& item : items) {
    const size_t eq = item.find('=');
    if (eq == std::string::npos || eq == 0)
      throw InputError("--dimension '" + item + "': expected CHANNEL=KIND, e.g. wind=speed");
    try {
      out[item.substr(0, eq)] = ParseDimension(item.substr(eq + 1));
    } catch (const InputError& e) {
      throw InputError("--dimension " + item + ": " + e.what());
    }
  }
  return out;
}

// F.record.json beside F.csv (docs/data.md#the-records-maneuver-frecordjson): the maneuver the
// log names, or, when it names none, no record file left from an earlier import. Returns the
// note for stderr, or "".
std::string WriteRecordFile(const ImportOptions& o, const Dataset& data) {
  const std::string record = RecordJsonPath(o.out);
  std::error_code ec;
  const auto maneuver = data.metadata().find("maneuver");
  if (maneuver == data.metadata().end()) {
    if (!std::filesystem::exists(record, ec)) return "";
    if (!std::filesystem::remove(record, ec) || ec)
      throw InputError(record +
                       ": cannot remove the earlier import's record file: " + ec.message());
    return "removed " + record + ", an earlier import's record file: this log names no maneuver";
  }
  const nlohmann::json j = {{"maneuver", maneuver->second},
                            {"imported_from", o.data},
                            {"format", o.format},
                            {"scale", o.scale}};
  try {
    WriteJsonFile(record, j);
  } catch (const InputError&) {
    std::filesystem::remove(record, ec);  // not an earlier import's record beside the new data
    throw;
  }
  return "the maneuver '" + maneuver->second + "' kept in " + record;
}

void RunImport(const ImportOptions& o) {
  const std::map<std::string, Dimension> dimensions = ParseDimensions(o.dimensions);
  if (!dimensions.empty() && o.scale == 1.0)
    throw InputError("--dimension: applies with --scale only");
  CheckOutputFile(o.out);
  ImportReport report;
  Dataset data;
  if (o.format == "marin-dat" || o.format == "hsva-dat") {
    if (!o.map.empty()) throw InputError("--map: applies to --format csv only");
    data = o.format == "marin-dat" ? ImportMarinDat(o.data, report) : ImportHsvaDat(o.data, report);
  } else {
    data = ImportCsvLog(o.data, ParseColumnMap(o.map), report);
  }
  if (!o.end_at_stop.empty())
    report.notes.push_back(DescribeRecordEnd(EndAtStop(data, o.end_at_stop), o.end_at_stop));
  if (data.rows() < 2) throw InputError(o.data + ": fewer than two rows left after repair");
  if (!o.rate_from.empty()) {
    if (data.Has("r")) throw InputError("--rate-from: the log already has a channel r");
    data.Set("r", RateFromHeading(data, o.rate_from));
    report.notes.push_back("r from the derivative of the smoothed, unwrapped " + o.rate_from);
  }
  if (!o.rate_bias_from.empty()) {
    if (!o.rate_from.empty())
      throw InputError("--rate-bias-from: r derived with --rate-from has no gyro's bias");
    const RateCalibration c = EstimateRateCalibration(data, o.rate_bias_from);
    data.Set("r", CalibratedRate(data, c));
    report.notes.push_back(DescribeRateCalibration(c, o.rate_bias_from));
  }
  if (o.scale != 1.0) {
    std::ostringstream s;
    s << "Froude-scaled by lambda = " << o.scale << ": t x" << std::sqrt(o.scale);
    for (const ScaledChannel& c : FroudeScale(data, o.scale, dimensions))
      s << ", " << c.channel << " x" << c.factor << " (" << c.dimension << ")";
    report.notes.push_back(s.str());
  }
  WriteDatasetCsv(o.out, data);
  if (std::string note = WriteRecordFile(o, data); !note.empty())
    report.notes.push_back(std::move(note));
  for (const std::string& note : report.notes) std::cerr << "usvid import: " << note << '\n';
  std::cerr << "usvid import: wrote " << o.out << " (" << data.rows() << " rows, "
            << data.channels().size() << " channels, " << data.duration() << " s)\n";
}

}  // namespace

void AddImportCommand(CLI::App& app) {
  auto o = std::make_shared<ImportOptions>();
  CLI::App* cmd = app.add_subcommand(
      "import",
      "Turn a foreign log into usvid's data CSV (units to SI, body velocities, time "
      "repaired and reported)");
  cmd->add_option("--format", o->format,
                  "Log format: marin-dat (MARIN .dat), hsva-dat (HSVA .dat, its maneuver kept in "
                  "F.record.json) or csv")
      ->required()
      ->check(CLI::IsMember({"marin-dat", "hsva-dat", "csv"}));
  cmd->add_option("--data", o->data, "The log to read")->required();
  cmd->add_option("--map", o->map,
                  "Column map for csv: NEW=OLD[:unit],... (units deg, deg/s, knots, km/h, rpm, "
                  "ms; targets vn, ve become body u, v); without it every column is kept")
      ->delimiter(',');
  cmd->add_option("--rate-from", o->rate_from,
                  "Add the rate of turn r [rad/s] from this heading channel [rad] (a log without "
                  "a gyro): unwrapped, smoothing-spline derivative");
  cmd->add_option("--rate-bias-from", o->rate_bias_from,
                  "Remove the rate of turn's offset and scale error, estimated against this "
                  "heading channel [rad] (a gyro's bias: the integral of r parts from the "
                  "heading's change); both on stderr");
  cmd->add_option("--end-at-stop", o->end_at_stop,
                  "End the record at the last row where this actuator channel (e.g. n) still "
                  "runs: the recovery after a test, driven by what the log does not hold, is "
                  "dropped; the time and rows dropped on stderr");
  cmd->add_option("--scale", o->scale,
                  "Froude-scale the log by LAMBDA = L_target / L_log (> 1: model to full scale, "
                  "< 1: back): time and speeds x sqrt(LAMBDA), lengths x LAMBDA, rates and "
                  "revolutions / sqrt(LAMBDA), forces x LAMBDA^3, moments x LAMBDA^4; each "
                  "channel's factor on stderr");
  cmd->add_option("--dimension", o->dimensions,
                  "With --scale, the dimension of a channel the data contract does not name: "
                  "CHANNEL=length|speed|rate|revolutions|angle|acceleration|force|moment,...")
      ->delimiter(',');
  cmd->add_option(
         "--out", o->out,
         "The data CSV to write (and F.record.json beside it when the log names its maneuver)")
      ->required();
  cmd->callback([o] { RunImport(*o); });
}

}  // namespace usvid
