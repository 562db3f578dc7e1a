// A vessel folder's track file, DIR/NAME/track.yaml (docs/tracks.md): how `usvid compare --suite
// real --data-dir DIR` reads the folder's runs and what it does with them. Beside it the vessel
// file, DIR/NAME/vessel.yaml (docs/model.md#vessel-files), and the runs, in the folder and any
// subfolders. `usvid init-track` writes a first one from a log's header (harness/track_init.h).
//
//   name: my-usv                  # the track's name (default: the folder's)
//   vessel: vessel.yaml           # a file in the folder or a compiled vessel (default: vessel.yaml
//                                 # when the folder has one, else none: data-driven methods only)
//   format: csv-log               # csv-log (any CSV, with columns), csv (usvid's), marin-dat,
//                                 # hsva-dat
//   also: {.csv: csv}             # other files of the folders, by extension, and their format
//                                 # (csv, marin-dat, hsva-dat: no columns)
//   columns:                      # usvid's channel: the log's column[:unit] (csv-log only)
//     t: time
//     psi: heading:deg
//   rate_from: psi                # r from the heading, for a log without a gyro
//   end_at_stop: n                # each run ends where this input stopped
//   scale: 45.7                   # Froude scale to full scale (> 0; default 1)
//   runs:                         # the subfolders of runs ("." the folder itself) and the tests
//     zigzag: zigzag              # their runs hold: zigzag, turning, any (read from each record)
//     random: none                # or none (free runs); default: every subfolder, any
//   split:                        # optional; without it every run is held out in turn
//     train: [a.csv, b.csv]       # (leave-one-run-out cross-validation)
//     test:
//       - {file: zigzag/c.csv, maneuver: zigzag:20/20, name: zigzag 20}
//   methods: [nominal, sindy, {method: gp, base: vessel}]   # default: kDefaultTrackMethods
//
// Every error is InputError "track.yaml:line:column: key: what", exit 2 at the command line.
#pragma once

#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

namespace usvid {

// A subfolder of runs, relative to the vessel folder ("." for the folder itself), and the tests
// its runs hold: "zigzag", "turning", "any" or "" (free runs alone).
struct TrackRunFolder {
  std::string path;
  std::string tests;
};

// A mapped column and where the track file maps it, to name that line when a log lacks it.
struct TrackColumn {
  std::string target, source;
  int line = 0, column = 0;
};

struct TrackFile {
  std::string file;    // the track file's path
  std::string folder;  // the vessel folder
  std::string name;
  std::string vessel;   // a vessel file's path or a compiled vessel's name; "" for none
  nlohmann::json read;  // the suite data keys every run is read with (harness/suite_data.h)
  std::vector<TrackColumn> columns;
  std::vector<TrackRunFolder> folders;
  std::vector<std::pair<std::string, std::string>> also;  // extension -> format
  bool split = false;
  nlohmann::json train = nlohmann::json::array();  // suite data entries, files from the folder
  nlohmann::json test = nlohmann::json::array();
  nlohmann::json methods = nlohmann::json::array();
  // Whether the split's runs and the run folders must be there (a built-in track's absence is
  // the real suite's to report, as the files its data folder lacks).
  bool check_runs = true;
};

// The methods a track without "methods" compares: the particulars-only model and the
// identification methods that need no settings, each at its defaults; those that need a vessel
// (nominal, refit, fossen-ceres, grey-box GP) only when the track has one, and without one
// Nomoto's model of r from delta where the track has both (`channels`: those it maps).
nlohmann::json DefaultTrackMethods(bool has_vessel, const std::set<std::string>& channels);

// The file extensions `format` reads.
std::vector<std::string> RunExtensions(const std::string& format);

// Reads and checks DIR/NAME/track.yaml (`path`): unknown keys, channels, formats, tests and a
// scale not above 0 are refused with the file, line and key.
TrackFile ReadTrackFile(const std::string& path);

// A built-in track (harness/tracks/*.yaml, embedded): `text` read as the track file of `folder`,
// its errors named by `label`; its runs need not be there.
TrackFile ReadBuiltInTrack(const std::string& text, const std::string& label,
                           const std::string& folder);

// Checks that every column the track maps is in the header of the log `run` (format csv-log):
// InputError at the track file's line of the first that is not, naming the run.
void CheckColumnsOf(const TrackFile& track, const std::string& run);

}  // namespace usvid
