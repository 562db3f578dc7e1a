// usvid info --data F.csv: checks a data file against docs/data.md#data-files and summarises
// it: rows, duration, and per channel the samples taken, the sampling rate and the range.
// A propeller (n, rev or rpm) that stops before the record ends is reported with the seconds
// that follow it (preprocessing/record_end.h). With --zigzag [B]: the zig-zag test the record
// holds (metrics/maneuver_of_record.h: A, B unless given, side, execute, base course) and its
// overshoots (metrics/zigzag_response.h).

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "apps/usvid/commands.h"
#include "apps/usvid/data_file.h"
#include "core/csv_dataset.h"
#include "core/error.h"
#include "metrics/maneuver_of_record.h"
#include "metrics/recorded_yaw_rate.h"
#include "metrics/zigzag_response.h"
#include "preprocessing/record_end.h"

namespace usvid {
namespace {

// Median interval between the samples a channel took, in seconds (0 with fewer than two).
double MedianInterval(const Eigen::VectorXd& t, const Channel& c) {
  std::vector<double> gaps;
  double last = -1.0;
  bool have_last = false;
  c.ForEachSample([&](Eigen::Index i, double) {
    if (have_last) gaps.push_back(t(i) - last);
    last = t(i);
    have_last = true;
  });
  if (gaps.empty()) return 0.0;
  std::nth_element(gaps.begin(), gaps.begin() + gaps.size() / 2, gaps.end());
  return gaps[gaps.size() / 2];
}

// What the channels hold in memory, and which are held sparse (docs/data.md#multi-rate-channels):
// "held: 58.3 MB; sparse: north, east (0.173 MB, 1.3 % of their 13 MB dense)".
void PrintHeldMemory(const Dataset& d) {
  constexpr double kDenseBytesPerRow = sizeof(double) + sizeof(bool);
  double held = 0.0, sparse_held = 0.0, sparse_dense = 0.0;
  std::string sparse;
  for (const Channel& c : d.channels()) {
    held += static_cast<double>(c.StorageBytes());
    if (!c.Sparse()) continue;
    sparse += (sparse.empty() ? "" : ", ") + c.name;
    sparse_held += static_cast<double>(c.StorageBytes());
    sparse_dense += kDenseBytesPerRow * static_cast<double>(c.size());
  }
  std::printf("held: %.3g MB", held / 1e6);
  if (!sparse.empty())
    std::printf("; sparse: %s (%.3g MB, %.2g %% of their %.3g MB dense)", sparse.c_str(),
                sparse_held / 1e6, 100.0 * sparse_held / sparse_dense, sparse_dense / 1e6);
  std::printf("\n");
}

// "n stops at 127.1 s and the record goes on for 13.1 s: ..." for a propeller channel that stops
// for good before the last row; nothing for one that runs to the end, never runs or has gaps.
void PrintPropellerStop(const Dataset& d) {
  for (const char* channel : {"n", "rev", "rpm"}) {
    if (!d.Has(channel)) continue;
    RecordEnd end;
    try {
      end = FindRecordEnd(d, channel);
    } catch (const InputError&) {  // empty cells, or a propeller that never runs
      continue;
    }
    if (end.dropped_rows == 0) continue;
    std::printf(
        "%s stops at %.1f s and the record goes on for %.1f s: a test's end, or the recovery "
        "after it (import --end-at-stop %s drops it; docs/data.md#the-end-of-a-test)\n",
        channel, end.t_end, end.dropped_s, channel);
  }
}

// How fast the rudder channel [rad] moves in its large moves (metrics/recorded_yaw_rate.h): a move
// of 5 deg or more between two samples is a log of the rudder's orders. (Whether a replay steps
// them is the vessel's to say: ReplayYawRateLimit, against its rate.)
void PrintRudderRate(const Dataset& d, const std::string& rudder) {
  constexpr double kDeg = std::numbers::pi / 180.0;
  const double rate = LargeMoveRate(d, rudder, 2.0 * kDeg);
  if (!(rate > 0) || d.rows() < 2) return;
  const double period = d.duration() / static_cast<double>(d.rows() - 1);
  std::printf("rudder %s: its large moves at %.3g deg/s%s\n", rudder.c_str(), rate / kDeg,
              rate * period >= 5.0 * kDeg
                  ? " (steps between two samples: the log holds the rudder's orders; a "
                    "data-driven model's replay steps them where they outrun twice the vessel's "
                    "rate)"
                  : "");
}

struct InfoOptions {
  std::string data;
  bool zigzag = false;      // analyse as a zig-zag
  double zigzag_deg = 0.0;  // its heading check B; 0: read from the record
  std::string heading = "psi", rudder = "delta";
};

void RunInfo(const InfoOptions& o) {
  const std::string& path = o.data;
  const Dataset d = ReadDataFile(path, "usvid info");
  std::printf("%s: %ld rows, t from %g to %g s (%g s)\n", path.c_str(), static_cast<long>(d.rows()),
              d.t()(0), d.t()(d.rows() - 1), d.duration());
  std::printf("%-16s %9s %10s %14s %14s\n", "channel", "samples", "rate [Hz]", "min", "max");
  for (const Channel& c : d.channels()) {
    const long n = c.SampleCount();
    const double gap = MedianInterval(d.t(), c);
    double lo = n > 0 ? INFINITY : 0.0, hi = n > 0 ? -INFINITY : 0.0;
    c.ForEachSample([&](Eigen::Index, double v) { lo = std::min(lo, v), hi = std::max(hi, v); });
    std::printf("%-16s %9ld %10.4g %14.6g %14.6g\n", c.name.c_str(), n, gap > 0 ? 1.0 / gap : 0.0,
                lo, hi);
  }
  for (const Dataset::TextColumn& c : d.text_columns())
    std::printf("%-16s %9s\n", c.name.c_str(), "text");
  PrintHeldMemory(d);
  PrintPropellerStop(d);
  if (o.zigzag) {
    // The test read from the record (metrics/maneuver_of_record.h): A, B unless given, the side,
    // the execute and the base course; a log's name of its maneuver checked against it.
    const TestOfRecord test = ReadTestOfRecord(d, "zigzag", o.heading, o.rudder);
    const double a = test.kind.empty() ? o.zigzag_deg : test.rudder_deg;
    const double b = o.zigzag_deg > 0 ? o.zigzag_deg : test.check_deg;
    if (!(b > 0))
      throw InputError(path + ": --zigzag: no zig-zag to read its heading check B from (no "
                       "rudder reversal from full angle); give B, --zigzag B");
    const ZigzagResponse z = AnalyseZigzag(d, b, o.heading, o.rudder, a);
    const std::string source = o.zigzag_deg > 0   ? "given"
                               : test.named.empty() ? "read from the record"
                                                    : "named by the log ('" + test.named +
                                                          "', checked against the record)";
    std::printf(
        "zig-zag %g/%g (heading check B %s): executed at %g s, first turn to %s, reversed about "
        "a base course %+.2f deg off the heading at the execute\n",
        a, b, source.c_str(), z.execute_s, z.first_turn > 0 ? "starboard" : "port",
        z.base_offset_deg);
    for (size_t i = 0; i < z.overshoot_deg.size(); ++i)
      std::printf("  reversal %zu at %8.2f s: overshoot %6.2f deg%s\n", i + 1, z.reversal_s[i],
                  z.overshoot_deg[i],
                  i + 1 == z.overshoot_deg.size() ? " (record may end first)" : "");
    PrintRudderRate(d, o.rudder);
  }
}

}  // namespace

void AddInfoCommand(CLI::App& app) {
  auto o = std::make_shared<InfoOptions>();
  CLI::App* cmd = app.add_subcommand(
      "info", "Check a data CSV against the contract and summarise its channels and rates");
  cmd->add_option("--data", o->data, "The data CSV to check")->required();
  cmd->add_option("--zigzag", o->zigzag_deg,
                  "Analyse it as a zig-zag: overshoots after each rudder reversal (ITTC), with "
                  "the heading check B [deg] given, or read from the record without a value")
      ->expected(0, 1);
  cmd->add_option("--heading", o->heading, "Heading channel for --zigzag")->capture_default_str();
  cmd->add_option("--rudder", o->rudder, "Rudder channel for --zigzag")->capture_default_str();
  cmd->callback([o, cmd] {
    o->zigzag = cmd->count("--zigzag") > 0;
    if (!(o->zigzag_deg >= 0)) throw InputError("--zigzag: must be a positive angle [deg]");
    RunInfo(*o);
  });
}

}  // namespace usvid
