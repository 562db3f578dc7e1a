#include "harness/track_init.h"

#include <algorithm>
#include <cctype>
#include <set>

#include "core/error.h"

namespace usvid {
namespace {

// Each channel and the names logs give it, lower case, units and punctuation dropped; the first
// column that matches one of them, in the order listed, is taken.
struct Aliases {
  const char* channel;
  std::vector<const char*> names;
};

const std::vector<Aliases>& KnownNames() {
  static const std::vector<Aliases> known = {
      {"t", {"t", "time", "time_s", "t_s", "timestamp", "seconds"}},
      {"north", {"north", "x", "x0", "x_position", "x_position_mid", "pos_north", "x_m"}},
      {"east", {"east", "y", "y0", "y_position", "y_position_mid", "pos_east", "y_m"}},
      {"psi", {"psi", "psi_hat", "yaw", "heading", "hdg"}},
      {"u", {"u", "u_velo", "surge", "surge_speed"}},
      {"v", {"v", "vm_velo", "v_velo", "sway", "sway_speed"}},
      {"r", {"r", "r_angvelo", "yaw_rate", "yawrate", "rot"}},
      {"U", {"speed", "sog", "speed_over_ground", "u_total"}},
      {"vn", {"vn", "vel_north", "v_north"}},
      {"ve", {"ve", "vel_east", "v_east"}},
      {"delta", {"delta", "delta_rudder", "rudder", "rudder_angle", "delta_r"}},
      {"n", {"n", "n_prop", "rps", "prop_rps", "rpm", "prop_rpm"}},
      {"wind_speed",
       {"wind_speed", "wind_velo_relative_mid", "wind_velo_relative", "apparent_wind_speed"}},
      {"wind_direction",
       {"wind_direction", "wind_dir_relative_mid", "wind_dir_relative", "apparent_wind_angle"}}};
  return known;
}

// "x_position_mid [m]" -> "x_position_mid"; "Heading (deg)" -> "heading".
std::string Bare(const std::string& column) {
  std::string out;
  for (char c : column) {
    if (c == '[' || c == '(') break;
    out += std::isalnum(static_cast<unsigned char>(c)) ? static_cast<char>(std::tolower(c)) : '_';
  }
  while (!out.empty() && out.back() == '_') out.pop_back();
  while (!out.empty() && out.front() == '_') out.erase(out.begin());
  return out;
}

// The unit a column's header marks that usvid converts (core/units.h), as a map suffix.
std::string UnitSuffix(const std::string& column, const std::string& channel) {
  std::string lower;
  for (char c : column) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (lower.find("deg/s") != std::string::npos) return ":deg/s";
  if (lower.find("deg") != std::string::npos) return ":deg";
  if (channel == "n" && lower.find("rpm") != std::string::npos) return ":rpm";
  if (lower.find("knot") != std::string::npos || lower.find("[kn]") != std::string::npos)
    return ":knots";
  return "";
}

}  // namespace

RecognisedColumns RecogniseColumns(const std::vector<std::string>& columns) {
  RecognisedColumns out;
  std::set<std::string> used;
  for (const Aliases& a : KnownNames()) {
    bool found = false;
    for (const char* name : a.names) {
      for (const std::string& c : columns)
        if (!used.contains(c) && Bare(c) == name) {
          out.mapped.emplace_back(a.channel, c + UnitSuffix(c, a.channel));
          used.insert(c);
          found = true;
          break;
        }
      if (found) break;
    }
  }
  for (const std::string& c : columns)
    if (!used.contains(c)) out.unmapped.push_back(c);
  return out;
}

std::string TrackFileText(const std::string& name, const RecognisedColumns& columns,
                          const std::string& log, bool has_vessel) {
  // A YAML scalar: quoted when it holds what YAML reads otherwise (': ', '#', brackets).
  const auto scalar = [](const std::string& s) {
    if (s.find_first_of(":#[]{},&*!|>'\"%@`") == std::string::npos && !s.empty() &&
        s.front() != ' ' && s.front() != '-' && s.front() != '?')
      return s;
    std::string q = "\"";
    for (char c : s) q += (c == '"' || c == '\\') ? std::string("\\") + c : std::string(1, c);
    return q + "\"";
  };
  std::string out =
      "# usvid track file (docs/tracks.md): how `usvid compare --suite real --data-dir DIR` reads\n"
      "# the runs of this vessel folder. Written by usvid init-track from the header of\n"
      "# " +
      log +
      "; check each mapping, map what is left, and run.\n"
      "name: " +
      scalar(name) + "\n";
  if (!has_vessel)
    out +=
        "# No vessel.yaml in this folder: the data-driven methods alone. Add one (docs/model.md#\n"
        "# vessel-files) for the model from the main particulars, its refit and grey-box GP.\n";
  out +=
      "format: csv-log\ncolumns:  # usvid's channel: the log's column[:unit] (deg, deg/s, knots, "
      "rpm)\n";
  bool has_r = false, has_psi = false;
  for (const auto& [channel, column] : columns.mapped) {
    out += "  " + channel + ": " + scalar(column) + "\n";
    has_r = has_r || channel == "r";
    has_psi = has_psi || channel == "psi";
  }
  if (!columns.unmapped.empty()) {
    out += "  # not recognised; map those usvid should read (channels: docs/data.md#channels):\n";
    for (const std::string& c : columns.unmapped) out += "  #   ?: " + scalar(c) + "\n";
  }
  if (!has_r && has_psi) out += "rate_from: psi  # no yaw rate column: r from the heading\n";
  out +=
      "# runs:    # the subfolders of runs and the tests they hold (zigzag, turning, any, none);\n"
      "#          # default: the folder and every folder below it, tests read from each record\n"
      "# split:   # the runs to train on and to score; default: each run held out in turn\n"
      "#   train: [a.csv, b.csv]\n"
      "#   test: [{file: c.csv, maneuver: zigzag:20/20}]\n"
      "# methods: [sindy, gp]  # default: every method that needs no settings\n";
  return out;
}

}  // namespace usvid
