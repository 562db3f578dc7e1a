#include "harness/real_suite.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "core/atomic_file.h"
#include "core/error.h"
#include "harness/cross_validation.h"
#include "harness/embedded_suites.h"
#include "harness/suite_data.h"
#include "harness/suite_methods.h"
#include "harness/track_file.h"
#include "methods/gp/gp_identify.h"
#include "methods/hybrid/hybrid.h"
#include "methods/identify_request.h"
#include "methods/refit/refit.h"
#include "metrics/maneuver_of_record.h"

namespace usvid {
namespace {

namespace fs = std::filesystem;

// The most rows a fold's refit fits in a cross-validated track, spread over the fold's runs: two
// thirds of what the largest track trains on without --cv (Esso Osaka's eight runs, 30642
// rows), which puts the real suite's --cv within its 15 minutes on 2 cores (at 30000 it took
// 15 min 34 s, the refit 24.9 s a fold against 18.7; docs/compare.md#cross-validation-over-runs).
constexpr long kCrossValidationFitRows = 20000;

// A folder scanned for further test runs, from the data folder, and the test its runs hold:
// "zigzag", "turning", "any" (either, read from each record) or "" (free runs alone).
using RunFolder = TrackRunFolder;

// A further run's file extension and the suite format it is read in; "" for the format of the
// track's listed runs (with their column map).
struct RunFormat {
  std::string extension;
  std::string format;
};

struct TrackSpec {
  std::string name;
  // A built-in track's embedded file, by its path in the repository (harness/embedded_suites.h):
  // a suite (.json), or a track file (.yaml) read as its folder's track.yaml would be.
  std::string file;
  std::vector<RunFolder> folders;
  std::vector<RunFormat> formats{};
  // Trained in one tank and scored in another: not cross-validated over its runs (its folds would
  // mix the tanks), and skipped, with a note, when either tank's folder is absent.
  bool cross_facility = false;
  // A track file's track (a vessel folder's, harness/track_file.h, or a built-in one's,
  // harness/tracks/): cross-validated unless its track file splits the runs.
  bool from_track_file = false;
  bool split = true;
  nlohmann::json read{};      // the keys its runs are read with; a built-in track's first test's
  std::string vessel_file{};  // a built-in track file's vessel, embedded (a path as `file`)
};

// The keys a track's further runs are read with (format, column map, end, scale, rate).
const nlohmann::json& ReadKeys(const TrackSpec& spec, const nlohmann::json& suite) {
  return spec.from_track_file ? spec.read : suite["data"]["test"].at(0);
}

// KVLCC2's folder also takes data files of usvid's own format (docs/data.md): another tank's
// tests, imported (and Froude-scaled) with usvid import. HSVA's folder is a track of its own, and
// the two tanks each train the model the other scores (the cross-facility tracks).
const std::vector<TrackSpec>& Tracks() {
  static const std::vector<TrackSpec> tracks = {
      {.name = "kvlcc2", .file = "harness/tracks/kvlcc2.yaml", .folders = {{"kvlcc2-marin", ""}}},
      {.name = "esso-osaka",
       .file = "harness/tracks/esso-osaka.yaml",
       .folders = {{"esso-osaka", ""}},
       .vessel_file = "docs/vessels/files/esso-osaka.yaml"},
      {.name = "kvlcc2-hsva",
       .file = "harness/suites/real-kvlcc2-hsva.json",
       .folders = {{"kvlcc2-hsva", "any"}},
       .formats = {{".dat", ""}}},
      {.name = "kvlcc2-hsva-to-marin",
       .file = "harness/suites/real-kvlcc2-hsva-to-marin.json",
       .folders = {{"kvlcc2-marin", "any"}},
       .formats = {{".dat", ""}},
       .cross_facility = true},
      {.name = "kvlcc2-marin-to-hsva",
       .file = "harness/suites/real-kvlcc2-marin-to-hsva.json",
       .folders = {{"kvlcc2-hsva", "any"}},
       .formats = {{".dat", ""}},
       .cross_facility = true}};
  return tracks;
}

// The format `path` is read in, as `spec` maps its extension; nullptr for a file it does not
// read.
const std::string* FormatOf(const TrackSpec& spec, const fs::path& path) {
  for (const RunFormat& f : spec.formats)
    if (path.extension() == f.extension) return &f.format;
  return nullptr;
}

std::vector<std::string> FilesOf(const nlohmann::json& entry) {
  const nlohmann::json& f = entry.at("file");
  if (f.is_string()) return {f.get<std::string>()};
  return f.get<std::vector<std::string>>();
}

// Every data file of `suite` joined to `data_dir`; the relative names, as listed, into `listed`
// and the absent ones into `missing`.
void Resolve(nlohmann::json& suite, const fs::path& data_dir, std::set<std::string>& listed,
             std::vector<std::string>& missing) {
  for (const char* part : {"train", "test"})
    for (nlohmann::json& entry : suite["data"][part]) {
      std::vector<std::string> files = FilesOf(entry);
      for (std::string& f : files) {
        listed.insert(fs::path(f).lexically_normal().string());
        const fs::path path = data_dir / f;
        if (!fs::is_regular_file(path)) missing.push_back(f);
        f = path.lexically_normal().string();
      }
      if (entry["file"].is_string())
        entry["file"] = files[0];
      else
        entry["file"] = files;
    }
}

// The maneuver a further run of `folder` holds, read from the record (metrics/
// maneuver_of_record.h) when the folder holds tests; "" for a folder of free runs, a record
// without such a test, or one that cannot be read (its row then says why). A log that names its
// maneuver and is contradicted by its record, or names one usvid does not know, stops the suite
// (InputError naming the file): a test misread is worse than one left out.
std::string ManeuverOfFurtherRun(const nlohmann::json& entry, const RunFolder& folder) {
  if (folder.tests.empty()) return "";
  Dataset data;
  try {
    data = LoadSuiteData(ParseSuiteData(entry, "", "further run"));
  } catch (const InputError&) {
    return "";
  }
  if (data.metadata().contains("maneuver")) return ManeuverOfRecord(data, folder.tests);
  try {
    return ManeuverOfRecord(data, folder.tests);
  } catch (const InputError&) {
    return "";
  }
}

// The runs of the track's folders that the track does not list, sorted, as test entries like
// its first one (format, column map, end). A zig-zag or a turn, in a folder of tests, is
// re-run closed-loop as its record says (ManeuverOfFurtherRun); every run is scored by its
// free run.
std::vector<nlohmann::json> FurtherRuns(const TrackSpec& spec, const nlohmann::json& suite,
                                        const fs::path& data_dir,
                                        const std::set<std::string>& listed) {
  std::vector<std::pair<std::string, size_t>> found;  // (run, its folder's index)
  for (size_t i = 0; i < spec.folders.size(); ++i) {
    std::error_code ec;
    const fs::path folder = spec.folders[i].path;
    for (const fs::directory_entry& e : fs::directory_iterator(data_dir / folder, ec)) {
      if (!e.is_regular_file() || FormatOf(spec, e.path()) == nullptr) continue;
      const std::string relative = (folder / e.path().filename()).lexically_normal().string();
      if (!listed.contains(relative)) found.emplace_back(relative, i);
    }
  }
  std::sort(found.begin(), found.end());
  std::vector<nlohmann::json> out;
  const nlohmann::json& like = ReadKeys(spec, suite);
  for (const auto& [f, folder] : found) {
    const std::string format = *FormatOf(spec, f);
    nlohmann::json entry = {
        {"name", fs::path(f).stem().string()},
        {"format", format.empty() ? like.at("format").get<std::string>() : format},
        {"file", (data_dir / f).lexically_normal().string()}};
    if (like.contains("end_at_stop")) entry["end_at_stop"] = like["end_at_stop"];
    if (like.contains("map") && format.empty()) entry["map"] = like["map"];
    if (like.contains("scale") && format.empty()) entry["scale"] = like["scale"];
    if (like.contains("rate_from")) entry["rate_from"] = like["rate_from"];
    if (const std::string maneuver = ManeuverOfFurtherRun(entry, spec.folders[folder]);
        !maneuver.empty())
      entry["maneuver"] = maneuver;
    out.push_back(entry);
  }
  return out;
}

// The index of the folder of `spec` that holds `file` (a path under `data_dir`), or -1.
int FolderOf(const TrackSpec& spec, const fs::path& data_dir, const std::string& file) {
  const fs::path parent = fs::path(file).parent_path().lexically_normal();
  for (size_t i = 0; i < spec.folders.size(); ++i)
    if ((data_dir / spec.folders[i].path).lexically_normal() == parent) return static_cast<int>(i);
  return -1;
}

// The whole run's file (its folder and stem) that `file` is a cut copy of, by name
// ("turn_cut_X" of "turn_X"); "" for a file that is no cut copy.
std::string WholeRunOf(const std::string& file) {
  const std::string stem = fs::path(file).stem().string();
  for (const std::string mark : {"cut_", "_cut"})
    if (const size_t at = stem.find(mark); at != std::string::npos)
      return (fs::path(file).parent_path() / (stem.substr(0, at) + stem.substr(at + mark.size())))
          .string();
  return "";
}

// An entry's files, each a run of its own: named as ExpandCrossValidation names a file of an
// entry of several, ended at `end_at_stop` unless the entry says otherwise (null: as given), and
// given the maneuver its record holds when its folder holds tests, as a further run is
// (ManeuverOfFurtherRun).
std::vector<nlohmann::json> RunsOfEntry(const TrackSpec& spec, const fs::path& data_dir,
                                        const nlohmann::json& entry,
                                        const nlohmann::json& end_at_stop = nullptr) {
  std::vector<nlohmann::json> runs;
  const std::vector<std::string> files = FilesOf(entry);
  for (const std::string& f : files) {
    nlohmann::json run = entry;
    run["file"] = f;
    if (files.size() > 1)
      run["name"] = entry["name"].get<std::string>() + ": " + fs::path(f).stem().string();
    if (!end_at_stop.is_null() && !run.contains("end_at_stop")) run["end_at_stop"] = end_at_stop;
    const int folder = FolderOf(spec, data_dir, f);
    if (!run.contains("maneuver") && folder >= 0)
      if (const std::string m = ManeuverOfFurtherRun(run, spec.folders[folder]); !m.empty())
        run["maneuver"] = m;
    runs.push_back(std::move(run));
  }
  return runs;
}

// A track's training runs for cross-validation: each training file a run (RunsOfEntry), ended as
// the test runs are (their end_at_stop).
nlohmann::json TrainingRunsOf(const TrackSpec& spec, const fs::path& data_dir,
                              const nlohmann::json& suite) {
  const nlohmann::json like = ReadKeys(spec, suite);
  nlohmann::json train = nlohmann::json::array();
  for (const nlohmann::json& entry : suite["data"]["train"])
    for (nlohmann::json& run :
         RunsOfEntry(spec, data_dir, entry, like.value("end_at_stop", nlohmann::json())))
      train.push_back(std::move(run));
  return train;
}

// A suite's method entry's name: the entry itself, or its "method".
std::string MethodName(const nlohmann::json& m) {
  return m.is_string() ? m.get<std::string>() : m.value("method", "");
}

// diagnose and hybrid search and refit the vessel for each candidate: hundreds of seconds a fit
// on joined runs.
bool SearchesTheVessel(const nlohmann::json& m) {
  const std::string name = MethodName(m);
  return name == kDiagnoseMethod || name == hybrid::kMethodName;
}

// Leaves out of `suite`'s runs every cut copy of a run it holds whole (trained on while the whole
// run is held out, it would score the run on itself), with a note; returns how many runs are
// left. A test part left empty is erased: every run trains, and each is held out in turn.
size_t DropCutCopies(nlohmann::json& suite, std::vector<std::string>& notes) {
  std::map<std::string, std::string> whole;  // every run's file, without its extension -> name
  for (const char* part : {"train", "test"})
    for (const nlohmann::json& run : suite["data"][part]) {
      const fs::path f = run["file"].get<std::string>();
      whole[(f.parent_path() / f.stem()).string()] = run["name"].get<std::string>();
    }
  size_t runs = 0;
  for (const char* part : {"train", "test"}) {
    nlohmann::json kept = nlohmann::json::array();
    for (const nlohmann::json& run : suite["data"][part]) {
      const std::string of = WholeRunOf(run["file"].get<std::string>());
      if (!of.empty() && whole.contains(of)) {
        notes.push_back("'" + run["name"].get<std::string>() +
                        "' left out of the cross-validation: a cut copy of '" + whole[of] +
                        "', which the folder holds whole (trained on while that run is held out, "
                        "it would score the run on itself)");
        continue;
      }
      kept.push_back(run);
    }
    runs += kept.size();
    if (kept.empty() && std::string(part) == "test")
      suite["data"].erase("test");
    else
      suite["data"][part] = kept;
  }
  return runs;
}

// The methods a cross-validated track runs: without diagnose and hybrid, which search and refit
// the vessel for each candidate (200-500 s a fit on the tracks' joined runs, so hours over the
// folds; docs/compare.md#cross-validation-over-runs), and the refit at most
// kCrossValidationFitRows rows a fold: a fold trains on every run but one, up to four times the
// rows the track trains on without --cv (Esso Osaka: about 110000 against 30642), and the
// refit's time grows with its rows (54 s a fold on 60000, 27 folds), so each fold's refit takes
// at most kCrossValidationFitRows, spread over all the fold's runs (methods/refit/typed_refit.h).
// A track none of whose methods is left is an InputError naming `file`, its track file.
nlohmann::json CrossValidatedMethods(const nlohmann::json& given, const std::string& file,
                                     std::vector<std::string>& notes) {
  nlohmann::json methods = nlohmann::json::array();
  for (const nlohmann::json& m : given)
    if (!SearchesTheVessel(m)) methods.push_back(m);
  if (methods.empty())
    throw InputError(file +
                     ": methods: --cv leaves out diagnose and hybrid, and the track has no other "
                     "method to cross-validate");
  if (methods.size() < given.size())
    notes.push_back(
        "diagnose and hybrid left out of the cross-validation: each fits for 200-500 s on the "
        "joined runs, once per fold (they run in the suite without --cv)");
  bool capped = false;
  for (nlohmann::json& m : methods) {
    const std::string name = MethodName(m);
    if (name != kRefitMethodName) continue;
    if (m.is_string()) m = nlohmann::json{{"method", name}};
    const long rows = m.value("fit_rows", kCeresFitRows);
    if (rows == 0 || rows > kCrossValidationFitRows) {
      m["fit_rows"] = kCrossValidationFitRows;
      capped = true;
    }
  }
  if (capped)
    notes.push_back("each fold's refit fits at most " + std::to_string(kCrossValidationFitRows) +
                    " rows, spread over the fold's runs (the 60000 it takes at most without "
                    "--cv took 54 s a fold on Esso Osaka)");
  return methods;
}

// A track cross-validated over its runs (harness/cross_validation.h): its training files and
// test runs, each a run (TrainingRunsOf), but the cut copies of runs it holds whole
// (DropCutCopies), and its methods as CrossValidatedMethods says. What was done goes to `notes`.
void PrepareCrossValidation(const TrackSpec& spec, const std::string& cv, const fs::path& data_dir,
                            nlohmann::json& suite, std::vector<std::string>& notes) {
  const nlohmann::json like = ReadKeys(spec, suite);
  suite["data"]["train"] = TrainingRunsOf(spec, data_dir, suite);
  const size_t runs = DropCutCopies(suite, notes);
  suite["cv"] = cv;
  suite["methods"] = CrossValidatedMethods(suite["methods"], spec.file, notes);
  notes.push_back("leave-one-run-out cross-validation over " + std::to_string(runs) +
                  " runs: each left out in turn, every method fitted on the other " +
                  std::to_string(runs - 1) +
                  " jointly and scored on it (the training runs too re-run closed-loop as their "
                  "records say" +
                  (like.contains("end_at_stop")
                       ? ", and ended where " + like["end_at_stop"].get<std::string>() +
                             " stopped, as the test runs are)"
                       : std::string(")")));
}

// The vessel folders of `data_dir` (harness/track_file.h): its subfolders with a track.yaml.
std::vector<fs::path> VesselFolders(const fs::path& data_dir) {
  std::vector<fs::path> out;
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(data_dir, ec))
    if (e.is_directory() && fs::is_regular_file(e.path() / "track.yaml")) out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

// The runs of a vessel folder's track: every file of its folders in the track's format, relative
// to the data folder, sorted.
std::vector<std::string> RunsOf(const TrackSpec& spec, const fs::path& data_dir) {
  std::vector<std::string> runs;
  for (const RunFolder& folder : spec.folders) {
    std::error_code ec;
    for (const fs::directory_entry& e : fs::directory_iterator(data_dir / folder.path, ec))
      if (e.is_regular_file() && FormatOf(spec, e.path()) != nullptr)
        runs.push_back((fs::path(folder.path) / e.path().filename()).lexically_normal().string());
  }
  std::sort(runs.begin(), runs.end());
  return runs;
}

// A split's training runs as one entry, fitted on jointly: "<n> runs" (or the one run's name,
// with its cut).
nlohmann::json JoinedTraining(const TrackFile& track, const fs::path& folder) {
  if (track.train.size() == 1) {
    nlohmann::json entry = track.train[0];
    entry["file"] = (folder / entry["file"].get<std::string>()).lexically_normal().string();
    return entry;
  }
  // Read as its runs are, which must agree.
  nlohmann::json entry = track.train[0];
  entry.erase("maneuver");
  entry["name"] = std::to_string(track.train.size()) + " runs";
  entry["file"] = nlohmann::json::array();
  for (const nlohmann::json& run : track.train) {
    if (run.contains("from_s") || run.contains("to_s"))
      throw InputError(track.file + ": split.train: " + run["file"].get<std::string>() +
                       ": a cut (from_s, to_s) applies to a training run alone; the runs of a "
                       "split are fitted on jointly");
    for (const char* key : {"end_at_stop", "rate_from"})
      if (run.value(key, "") != track.train[0].value(key, ""))
        throw InputError(track.file + ": split.train: " + run["file"].get<std::string>() + ": " +
                         key +
                         " differs from the first training run's; the runs of a split "
                         "are read alike and fitted on jointly");
    entry["file"].push_back((folder / run["file"].get<std::string>()).lexically_normal().string());
  }
  return entry;
}

// The spec of a track file's track: its name, the folders of its runs (relative to the data
// folder; by default the vessel folder `path` and every folder below it, tests read from each
// run) and the format they are read in.
TrackSpec SpecOfTrack(const TrackFile& track, const fs::path& path, const fs::path& data_dir) {
  const fs::path folder = path.lexically_relative(data_dir);
  TrackSpec spec;
  spec.name = track.name;
  spec.file = track.file;
  spec.from_track_file = true;
  spec.split = track.split;
  spec.read = track.read;
  for (const std::string& ext : RunExtensions(track.read["format"].get<std::string>()))
    spec.formats.push_back({ext, ""});
  for (const auto& [ext, format] : track.also) spec.formats.push_back({ext, format});
  for (const TrackRunFolder& f : track.folders) {
    fs::path runs = (folder / f.path).lexically_normal();
    if (!runs.has_filename()) runs = runs.parent_path();  // "NAME/." is NAME
    spec.folders.push_back({runs.string(), f.tests});
  }
  if (track.folders.empty()) {
    spec.folders.push_back({folder.string(), "any"});
    std::error_code ec;
    for (const fs::directory_entry& e : fs::recursive_directory_iterator(path, ec))
      if (e.is_directory())
        spec.folders.push_back({e.path().lexically_relative(data_dir).string(), "any"});
    std::sort(spec.folders.begin() + 1, spec.folders.end(),
              [](const RunFolder& a, const RunFolder& b) { return a.path < b.path; });
  }
  return spec;
}

// The suite of a track file's track, its files relative to the data folder: the split's runs,
// or with one run and no split its two parts; the further runs are added as for every track.
nlohmann::json SuiteOfTrack(const TrackFile& track, const fs::path& folder,
                            const std::vector<std::string>& runs, const fs::path& data_dir) {
  nlohmann::json suite = {
      {"name", "real-" + track.name},
      {"vessels",
       track.vessel.empty() ? nlohmann::json::array() : nlohmann::json::array({track.vessel})},
      {"data", {{"train", nlohmann::json::array()}, {"test", nlohmann::json::array()}}},
      {"methods", track.methods},
      {"seeds", {1}}};
  nlohmann::json& data = suite["data"];
  if (track.split) {
    data["train"].push_back(JoinedTraining(track, folder));
    for (nlohmann::json entry : track.test) {
      entry["file"] = (folder / entry["file"].get<std::string>()).lexically_normal().string();
      data["test"].push_back(entry);
    }
  } else if (runs.size() == 1) {
    // One run, no split: its first two thirds train, its last third tests.
    nlohmann::json whole = track.read;
    whole["name"] = "run";
    whole["file"] = (data_dir / runs[0]).string();
    const Dataset d = LoadSuiteData(ParseSuiteData(whole, "", track.file));
    const double cut = d.t()(0) + 2.0 / 3.0 * (d.t()(d.rows() - 1) - d.t()(0));
    const std::string stem = fs::path(runs[0]).stem().string();
    nlohmann::json first = track.read, last = track.read;
    first["name"] = stem + ", first two thirds";
    first["file"] = runs[0];
    first["to_s"] = cut;
    last["name"] = stem + ", last third";
    last["file"] = runs[0];
    last["from_s"] = cut;
    data["train"].push_back(first);
    data["test"].push_back(last);
  }
  return suite;
}

// A vessel folder's track (harness/track_file.h): its spec, its suite and its runs, files
// relative to `data_dir`. False, with the reason in `skipped`, for a folder without runs.
bool VesselFolderTrack(const fs::path& path, const fs::path& data_dir, TrackSpec& spec,
                       nlohmann::json& suite, std::vector<std::string>& runs,
                       std::string& skipped) {
  const TrackFile track = ReadTrackFile((path / "track.yaml").string());
  spec = SpecOfTrack(track, path, data_dir);
  runs = RunsOf(spec, data_dir);
  if (runs.empty()) {
    std::string extensions;
    for (const RunFormat& f : spec.formats)
      extensions += (extensions.empty() ? "" : ", ") + f.extension;
    skipped = track.name + " (" + path.string() + "): no runs (" + extensions +
              " files of format " + track.read["format"].get<std::string>() +
              ") in the folder or below it";
    return false;
  }
  for (const std::string& run : runs) CheckColumnsOf(track, (data_dir / run).string());
  suite = SuiteOfTrack(track, path.lexically_relative(data_dir), runs, data_dir);
  return true;
}

// A built-in track's spec and suite: its own suite file, or its track file read as the track
// file of its folder in `data_dir`, the embedded vessel named "@FILE".
void BuiltInTrack(const TrackSpec& built_in, const fs::path& data_dir, TrackSpec& spec,
                  nlohmann::json& suite) {
  const std::string_view text = EmbeddedText(built_in.file);
  if (!built_in.file.ends_with(".yaml")) {
    spec = built_in;
    suite = nlohmann::json::parse(text, nullptr, true, /*ignore_comments=*/true);
    return;
  }
  const fs::path path = data_dir / built_in.folders[0].path;
  TrackFile track =
      ReadBuiltInTrack(std::string(text), built_in.file + " (built in)", path.string());
  if (!built_in.vessel_file.empty()) track.vessel = "@" + built_in.vessel_file;
  spec = SpecOfTrack(track, path, data_dir);
  suite = SuiteOfTrack(track, path.lexically_relative(data_dir), {}, data_dir);
}

// What the real suite found in a data folder: its tracks, each with its suite, and what it left
// out and why.
struct Gathered {
  std::vector<SuiteTrack> tracks;
  std::vector<nlohmann::json> suites;
  std::vector<std::string> missing;          // runs absent, or "FOLDER/ (all N ...)"
  bool partly_missing = false;               // a track with some of its runs
  std::vector<std::string> no_hsva;          // tracks skipped for want of kvlcc2-hsva/
  std::vector<std::string> absent;           // built-in tracks none of whose runs are there
  std::vector<std::string> skipped_folders;  // vessel folders without runs, and why
};

std::string CommaList(const std::vector<std::string>& items) {
  std::string out;
  for (const std::string& s : items) out += (out.empty() ? "" : ", ") + s;
  return out;
}

// One tank's KVLCC2 runs, as its track reads them, for the track of both tanks: the shared runs
// (the track's training and test entries, one file each) and the further runs of its folder,
// each named with its tank; cross-validated, every run is shared (its track made each a run).
struct TankRuns {
  std::string tank;
  std::optional<size_t> track;  // its track's index among the gathered ones
  nlohmann::json shared = nlohmann::json::array(), further = nlohmann::json::array();
};

TankRuns TankRunsOf(const std::string& tank, const TrackSpec& spec, const nlohmann::json& suite,
                    size_t further, const fs::path& data_dir) {
  TankRuns runs;
  runs.tank = tank;
  auto named = [&](nlohmann::json run) {
    const std::string name = run.at("name").get<std::string>();
    if (name.find(runs.tank) == std::string::npos) run["name"] = runs.tank + " " + name;
    return run;
  };
  for (const char* part : {"train", "test"}) {
    const nlohmann::json& entries = suite["data"].value(part, nlohmann::json::array());
    const size_t shared = std::string(part) == "test" ? entries.size() - further : entries.size();
    for (size_t i = 0; i < entries.size(); ++i) {
      if (i >= shared) {
        runs.further.push_back(named(entries[i]));
        continue;
      }
      // A shared run trains: with the maneuver its record holds, for the methods that choose
      // among their models by re-running the training runs' tests (grey-box GP).
      for (nlohmann::json& run : RunsOfEntry(spec, data_dir, entries[i]))
        runs.shared.push_back(named(std::move(run)));
    }
  }
  return runs;
}

// Whether a suite's method entry is grey-box GP (GP given a base model).
bool IsGreyBoxGp(const nlohmann::json& m) {
  return m.is_object() && m.value("method", "") == gp::kMethodName && m.contains("base");
}

// KVLCC2 of both tanks as one track (docs/compare.md#kvlcc2-both-tanks): MARIN's shared runs and
// HSVA's, trained on jointly. Without --cv it scores the further runs of both folders (none:
// no track, a note on MARIN's); cross-validated it takes the place of the two tanks' own tracks,
// every run of both left out in turn, so that a KVLCC2 model is judged over all twelve shared
// runs rather than MARIN's three. diagnose and hybrid (hundreds of seconds a fit on the joined
// runs) are left out, and cross-validated grey-box GP too: its choice re-runs the training runs'
// tests, 58 s a fold on eleven runs against GP's 17 s.
void AddTwoTankTrack(const TankRuns& marin, const TankRuns& hsva, const std::string& cv,
                     Gathered& g) {
  const bool cross_validated = !cv.empty();
  nlohmann::json further = marin.further;
  further.insert(further.end(), hsva.further.begin(), hsva.further.end());
  if (!cross_validated && further.empty()) {
    g.tracks[*marin.track].notes.push_back(
        "kvlcc2-both-tanks not run: no further run in kvlcc2-marin/ or kvlcc2-hsva/ to score "
        "the model of both tanks' shared runs on (--cv runs judges it over those runs)");
    return;
  }
  nlohmann::json suite = g.suites[*marin.track];
  suite["name"] = "real-kvlcc2-both-tanks";
  nlohmann::json runs = marin.shared;
  runs.insert(runs.end(), hsva.shared.begin(), hsva.shared.end());
  suite["data"] = {{"train", runs}};
  if (!further.empty()) suite["data"]["test"] = further;
  nlohmann::json methods = nlohmann::json::array();
  bool grey_box = false;
  for (const nlohmann::json& m : g.suites[*marin.track]["methods"]) {
    if (SearchesTheVessel(m)) continue;
    if (cross_validated && IsGreyBoxGp(m)) {
      grey_box = true;
      continue;
    }
    methods.push_back(m);
  }
  suite["methods"] = methods;
  SuiteTrack track;
  track.name = "kvlcc2-both-tanks";
  const size_t n = marin.shared.size() + hsva.shared.size();
  std::ostringstream what;
  what << "KVLCC2 of both tanks as one track: MARIN's " << marin.shared.size()
       << " runs and HSVA's " << hsva.shared.size();
  if (cross_validated)
    what << ", each left out in turn, every method fitted on the other " << n - 1
         << " jointly (in the place of the two tanks' own tracks)";
  else
    what << ", trained on jointly, scored on " << further.size()
         << (further.size() == 1 ? " further run" : " further runs") << " of the two folders";
  track.notes.push_back(what.str() + "; diagnose and hybrid left out (hundreds of seconds a fit)" +
                        (grey_box ? ", and grey-box GP (its choice re-runs the training runs' "
                                    "tests: about a minute a fold)"
                                  : ""));
  std::set<std::string> said;
  for (const TankRuns* tank : {&marin, &hsva})
    for (const std::string& note : g.tracks[*tank->track].notes)
      if (!note.starts_with("leave-one-run-out") && !note.starts_with("diagnose and hybrid") &&
          said.insert(note).second)
        track.notes.push_back(tank->tank + ": " + note);
  if (!cross_validated) {
    g.suites.push_back(std::move(suite));
    g.tracks.push_back(std::move(track));
    return;
  }
  suite["cv"] = cv;
  g.suites[*marin.track] = std::move(suite);
  g.tracks[*marin.track] = std::move(track);
  g.suites.erase(g.suites.begin() + static_cast<std::ptrdiff_t>(*hsva.track));
  g.tracks.erase(g.tracks.begin() + static_cast<std::ptrdiff_t>(*hsva.track));
}

// The built-in tracks whose runs the data folder holds; one whose folder holds a track file of
// its own is a vessel folder's (`own`).
void AddBuiltInTracks(const std::string& data_dir, const std::string& cv,
                      const std::set<std::string>& own, bool vessel_folders, Gathered& g) {
  TankRuns marin_runs, hsva_runs;
  for (const TrackSpec& built_in : Tracks()) {
    if (built_in.cross_facility && !cv.empty()) continue;  // its folds would mix the tanks
    if (own.contains(fs::path(built_in.folders[0].path).begin()->string())) continue;
    TrackSpec spec;
    nlohmann::json suite;
    BuiltInTrack(built_in, data_dir, spec, suite);
    std::set<std::string> listed;
    std::vector<std::string> lacks;
    Resolve(suite, data_dir, listed, lacks);
    // HSVA's tank is newer in the shared data than MARIN's and Esso Osaka's: a folder without it
    // runs the other tracks.
    const bool hsva = std::string(spec.name).find("hsva") != std::string::npos;
    if (hsva && !lacks.empty() && !fs::is_directory(fs::path(data_dir) / "kvlcc2-hsva")) {
      (vessel_folders ? g.absent : g.no_hsva).push_back(spec.name);
      continue;
    }
    if (lacks.size() == listed.size()) {  // the whole vessel is absent: name its folder
      g.missing.push_back(fs::path(spec.folders[0].path).begin()->string() + "/ (all " +
                          std::to_string(listed.size()) + " of the track's runs)");
      g.absent.push_back(spec.name);
      continue;
    }
    g.partly_missing = g.partly_missing || !lacks.empty();
    g.missing.insert(g.missing.end(), lacks.begin(), lacks.end());
    SuiteTrack track;
    track.name = spec.name;
    const std::vector<nlohmann::json> further = FurtherRuns(spec, suite, data_dir, listed);
    for (const nlohmann::json& entry : further) suite["data"]["test"].push_back(entry);
    if (further.empty())
      track.notes.push_back(
          "the data folder holds only the shared runs: trained and tested on "
          "those (the papers' own test runs are not there)");
    else
      track.notes.push_back(std::to_string(further.size()) +
                            (further.size() == 1 ? " further run" : " further runs") +
                            " of the data folder scored as held-out tests (free runs; the "
                            "zig-zags and turns also re-run closed-loop, their angle and side "
                            "read from the record)");
    if (!cv.empty()) PrepareCrossValidation(spec, cv, data_dir, suite, track.notes);
    if (spec.name == "kvlcc2" || spec.name == "kvlcc2-hsva") {
      const bool at_marin = spec.name == "kvlcc2";
      TankRuns& tank = at_marin ? marin_runs : hsva_runs;
      // Cross-validated, the further runs are runs like any (PrepareCrossValidation).
      tank = TankRunsOf(at_marin ? "MARIN" : "HSVA", spec, suite, cv.empty() ? further.size() : 0,
                        data_dir);
      tank.track = g.tracks.size();
    }
    g.suites.push_back(std::move(suite));
    g.tracks.push_back(std::move(track));
  }
  if (marin_runs.track && hsva_runs.track) AddTwoTankTrack(marin_runs, hsva_runs, cv, g);
}

// Every vessel folder's track: split as its track file says, else each run held out in turn.
void AddVesselFolderTracks(const std::string& data_dir, const std::string& cv,
                           const std::vector<fs::path>& folders, Gathered& g) {
  for (const fs::path& path : folders) {
    TrackSpec spec;
    nlohmann::json suite;
    std::vector<std::string> run_files;
    std::string why;
    if (!VesselFolderTrack(path, data_dir, spec, suite, run_files, why)) {
      g.skipped_folders.push_back(why);
      continue;
    }
    for (const SuiteTrack& t : g.tracks)
      if (t.name == spec.name)
        throw InputError((path / "track.yaml").string() + ": a second track named '" + spec.name +
                         "' in " + data_dir + " (give each vessel folder's track its own name:)");
    std::set<std::string> listed;
    std::vector<std::string> lacks;
    Resolve(suite, data_dir, listed, lacks);
    SuiteTrack track;
    track.name = spec.name;
    const std::vector<nlohmann::json> further = FurtherRuns(spec, suite, data_dir, listed);
    const size_t runs = run_files.size();
    // Without a split every run is one to train on, and each is held out in turn.
    const char* part = spec.split || runs == 1 ? "test" : "train";
    for (const nlohmann::json& entry : further) suite["data"][part].push_back(entry);
    const size_t tests = suite["data"]["test"].size();
    track.notes.push_back(
        "the vessel folder " + path.string() + " (its track.yaml): " + std::to_string(runs) +
        (runs == 1    ? " run: its first two thirds trained on, its last third scored"
         : spec.split ? " runs: trained on the split's " + std::to_string(runs - tests) +
                            ", scored on the other " + std::to_string(tests)
                      : " runs, each held out in turn (no split in track.yaml)"));
    std::string kind = spec.split || runs == 1 ? cv : std::string(kCrossValidationRuns);
    if (runs == 1 && !kind.empty()) {
      track.notes.push_back("not cross-validated: one run");
      kind.clear();
    }
    if (!kind.empty()) PrepareCrossValidation(spec, kind, data_dir, suite, track.notes);
    g.suites.push_back(std::move(suite));
    g.tracks.push_back(std::move(track));
  }
}

// The embedded vessel files a track names ("@PATH", its path in the repository) written to
// `vessel_dir` under their file names, and named there.
void WriteEmbeddedVessels(nlohmann::json& suite, const std::string& vessel_dir) {
  for (nlohmann::json& vessel : suite["vessels"]) {
    const std::string name = vessel.get<std::string>();
    if (!name.starts_with("@")) continue;
    EnsureOutputDirectory(vessel_dir);
    const std::string path = (fs::path(vessel_dir) / fs::path(name.substr(1)).filename()).string();
    WriteFileAtomically(path, std::string(EmbeddedText(name.substr(1))));
    vessel = path;
  }
}

}  // namespace

std::vector<SuiteTrack> RealSuiteTracks(const std::string& data_dir, const std::string& vessel_dir,
                                        const std::string& cv) {
  // A data folder of vessel folders runs them; a built-in track's folder with a track file of its
  // own is such a folder, and a built-in track none of whose runs are there is left out.
  const std::vector<fs::path> vessel_folders = VesselFolders(data_dir);
  std::set<std::string> own;
  for (const fs::path& f : vessel_folders) own.insert(f.filename().string());
  Gathered g;
  AddBuiltInTracks(data_dir, cv, own, !vessel_folders.empty(), g);
  AddVesselFolderTracks(data_dir, cv, vessel_folders, g);
  // A track with some of its runs is an error; one with none is left out when another runs.
  if (g.partly_missing || (g.tracks.empty() && g.skipped_folders.empty() && !g.missing.empty()))
    throw InputError("compare --suite real: the data folder " + data_dir + " lacks " +
                     CommaList(g.missing) + " (docs/compare.md#the-real-suite)");
  if (g.tracks.empty())
    throw InputError(
        "compare --suite real: no track to run in " + data_dir +
        (g.skipped_folders.empty() ? std::string() : ": " + g.skipped_folders.front()) +
        " (docs/tracks.md)");
  for (size_t i = 0; i < g.tracks.size(); ++i) {
    WriteEmbeddedVessels(g.suites[i], vessel_dir);
    g.tracks[i].suite = ParseSuite(g.suites[i], "embedded suite real, track " + g.tracks[i].name);
  }
  std::vector<std::string>& notes = g.tracks.front().notes;
  if (!g.no_hsva.empty())
    notes.push_back("tracks " + CommaList(g.no_hsva) + " skipped: the data folder " + data_dir +
                    " has no kvlcc2-hsva/");
  for (const std::string& why : g.skipped_folders) notes.push_back("vessel folder skipped: " + why);
  if (!g.absent.empty())
    notes.push_back("built-in tracks " + CommaList(g.absent) + " left out: none of their runs in " +
                    data_dir);
  return g.tracks;
}

}  // namespace usvid
