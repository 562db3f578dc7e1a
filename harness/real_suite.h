// The embedded suite on measured data (usvid compare --suite real; docs/compare.md#the-real-suite):
// one track per vessel, each a suite of its own with its own verdict, its files read from a data
// folder (../shared/data by default):
// - kvlcc2: MARIN's free-running KVLCC2 tests (harness/suites/real-kvlcc2.json);
// - esso-osaka: the Esso Osaka pond tests, with the particulars-only vessel file
//   (harness/suites/real-esso-osaka.json, docs/vessels/files/esso-osaka.yaml, both embedded).
// Each track trains on fixed shared runs and tests on the other shared runs and on every further
// run of its folders: a folder that also holds the papers' test runs scores the models on them.
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

// The names `usvid compare --suite` takes besides a file: default, quick, realistic and real.
const std::vector<std::string>& EmbeddedSuiteNames();

// Whether `suite` names an embedded suite rather than a file: no '/' and no '.' in it.
bool IsSuiteName(const std::string& suite);

// The real suite's tracks on the files of `data_dir`. The embedded vessel files are written to
// `vessel_dir` (created), and the tracks name them there. Throws InputError, one line naming the
// folder and the files it lacks, when a track's training or test files are not all there.
std::vector<SuiteTrack> RealSuiteTracks(const std::string& data_dir, const std::string& vessel_dir);

}  // namespace usvid
