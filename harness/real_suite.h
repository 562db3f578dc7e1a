// The embedded suite on measured data (usvid compare --suite real; docs/compare.md#the-real-suite):
// one track per vessel, each a suite of its own with its own verdict, its files read from a data
// folder (../shared/data by default):
// - kvlcc2: MARIN's free-running KVLCC2 tests (the track file harness/tracks/kvlcc2.yaml);
// - esso-osaka: the Esso Osaka pond tests, with the particulars-only vessel file: the track file
//   harness/tracks/esso-osaka.yaml, read as its folder's track.yaml would be, with
//   docs/vessels/files/esso-osaka.yaml (both embedded);
// - kvlcc2-hsva and the cross-facility tracks between the two tanks (harness/suites/);
// - kvlcc2-both-tanks: KVLCC2 trained on both tanks' shared runs jointly, scored on the further
//   runs of either folder (without any, not run); cross-validated, it takes the place of the two
//   tanks' own tracks, all twelve shared runs left out in turn;
// - every vessel folder DIR/NAME of the data folder with a track.yaml (harness/track_file.h,
//   docs/tracks.md): split as its track file says, else cross-validated over its runs.
// Each track trains on fixed shared runs and tests on the other shared runs and on every further
// run of its folders: a folder that also holds the papers' test runs scores the models on them.
// A built-in track none of whose runs are in the data folder is left out when another runs.
// Cross-validated (usvid compare --suite real --cv runs; harness/cross_validation.h), every one
// of those runs is left out in turn, each read as the track's test runs are (ended where the
// propeller stopped), a zig-zag or turn among the training runs too re-run closed-loop as its
// record says; a cut copy of a run the folder also holds whole is left out (trained on while the
// whole run is held out, it would score the run on itself), and a note says so.
#pragma once

#include <string>
#include <vector>

#include "harness/suite.h"

namespace usvid {

struct SuiteTrack {
  std::string name;  // the output's sub-folder
  Suite suite;
  // What the track found in the folder: the runs it added as held-out tests, or that it has
  // only the shared runs.
  std::vector<std::string> notes;
};

// The real suite's tracks on the files of `data_dir`. The embedded vessel files are written to
// `vessel_dir` (created), and the tracks name them there. `cv`: "" or the cross-validation's kind
// ("runs"). Throws InputError, one line naming the folder and the files it lacks, when a track's
// training or test files are not all there (or, cross-validated, naming the track and what is
// wrong with its runs).
std::vector<SuiteTrack> RealSuiteTracks(const std::string& data_dir, const std::string& vessel_dir,
                                        const std::string& cv = "");

}  // namespace usvid
