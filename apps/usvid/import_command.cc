// usvid import --format marin-dat|csv --data LOG [--map NEW=OLD[:unit],...] --out F.csv

#include <iostream>
#include <memory>

#include "apps/usvid/commands.h"
#include "core/csv_dataset.h"
#include "core/error.h"
#include "importers/csv_log.h"
#include "importers/marin_dat.h"
#include "preprocessing/heading_rate.h"

namespace usvid {
namespace {

struct ImportOptions {
  std::string format;
  std::string data;
  std::vector<std::string> map;
  std::string rate_from;
  std::string out;
};

void RunImport(const ImportOptions& o) {
  ImportReport report;
  Dataset data;
  if (o.format == "marin-dat") {
    if (!o.map.empty()) throw InputError("--map: applies to --format csv only");
    data = ImportMarinDat(o.data, report);
  } else {
    data = ImportCsvLog(o.data, ParseColumnMap(o.map), report);
  }
  if (data.rows() < 2) throw InputError(o.data + ": fewer than two rows left after repair");
  if (!o.rate_from.empty()) {
    if (data.Has("r")) throw InputError("--rate-from: the log already has a channel r");
    data.Set("r", RateFromHeading(data, o.rate_from));
    report.notes.push_back("r from the derivative of the smoothed, unwrapped " + o.rate_from);
  }
  WriteDatasetCsv(o.out, data);
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
  cmd->add_option("--format", o->format, "Log format: marin-dat (MARIN .dat) or csv")
      ->required()
      ->check(CLI::IsMember({"marin-dat", "csv"}));
  cmd->add_option("--data", o->data, "The log to read")->required();
  cmd->add_option("--map", o->map,
                  "Column map for csv: NEW=OLD[:unit],... (units deg, deg/s, knots, km/h, rpm, "
                  "ms; targets vn, ve become body u, v); without it every column is kept")
      ->delimiter(',');
  cmd->add_option("--rate-from", o->rate_from,
                  "Add the rate of turn r [rad/s] from this heading channel [rad] (a log without "
                  "a gyro): unwrapped, smoothing-spline derivative");
  cmd->add_option("--out", o->out, "The data CSV to write")->required();
  cmd->callback([o] { RunImport(*o); });
}

}  // namespace usvid
