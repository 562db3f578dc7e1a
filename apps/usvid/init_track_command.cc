// usvid init-track DIR/NAME --data FILE...: a vessel folder's first track.yaml (docs/tracks.md),
// from the header of the first log (harness/track_init.h): the columns usvid recognises mapped,
// the rest listed for the user to map. A log outside the folder is copied into it, and --vessel
// copies a vessel file in as vessel.yaml, so that `usvid compare --suite real --data-dir DIR`
// runs the folder next.

#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "apps/usvid/commands.h"
#include "core/atomic_file.h"
#include "core/csv_tokenizer.h"
#include "core/error.h"
#include "harness/track_file.h"
#include "harness/track_init.h"
#include "importers/csv_log.h"
#include "simulation/vessel_file.h"

namespace usvid {
namespace {

namespace fs = std::filesystem;

struct InitTrackOptions {
  std::string folder;
  std::vector<std::string> data;
  std::string vessel;
  bool force = false;
};

// Whether `file` is inside `folder` (or below it).
bool Inside(const std::string& file, const fs::path& folder) {
  const fs::path relative =
      fs::weakly_canonical(file).lexically_relative(fs::weakly_canonical(folder));
  return !relative.empty() && *relative.begin() != "..";
}

void RunInitTrack(const InitTrackOptions& o) {
  const fs::path folder = o.folder;
  const fs::path track_path = folder / "track.yaml";
  if (fs::exists(track_path) && !o.force)
    throw InputError(track_path.string() + ": already there (--force writes over it)");
  // Everything is checked before anything is written: the logs, the copies they need, the
  // first one's header and the vessel file.
  std::vector<std::string> copies;
  for (const std::string& f : o.data) {
    if (!fs::is_regular_file(f)) throw InputError(f + ": no such log");
    if (Inside(f, folder)) continue;
    if (fs::exists(folder / fs::path(f).filename()))
      throw InputError((folder / fs::path(f).filename()).string() +
                       ": already there (a run of that name)");
    copies.push_back(f);
  }
  const std::vector<std::string> columns = CsvLogColumns(o.data.at(0));
  if (!o.vessel.empty()) ReadVesselFile(o.vessel);
  EnsureOutputDirectory(folder.string());
  for (const std::string& f : copies) {
    WriteFileAtomically((folder / fs::path(f).filename()).string(), ReadTextFile(f));
    std::cerr << "usvid init-track: copied " << f << " into " << folder.string() << '\n';
  }
  if (!o.vessel.empty()) {
    WriteFileAtomically((folder / "vessel.yaml").string(), ReadTextFile(o.vessel));
    std::cerr << "usvid init-track: copied " << o.vessel << " to "
              << (folder / "vessel.yaml").string() << '\n';
  }
  const bool has_vessel = fs::is_regular_file(folder / "vessel.yaml");
  const RecognisedColumns recognised = RecogniseColumns(columns);
  fs::path clean = folder.lexically_normal();
  if (!clean.has_filename()) clean = clean.parent_path();  // DIR/NAME/
  const fs::path vessels = clean.parent_path();            // DIR, what compare is given
  const std::string name = fs::absolute(clean).filename().string();
  WriteFileAtomically(track_path.string(),
                      TrackFileText(name.empty() ? "vessel" : name, recognised,
                                    fs::path(o.data[0]).filename().string(), has_vessel));
  ReadTrackFile(track_path.string());  // what it wrote reads back
  std::cout << "usvid init-track: wrote " << track_path.string() << ": " << recognised.mapped.size()
            << " columns mapped";
  for (const auto& [channel, column] : recognised.mapped)
    std::cout << ", " << channel << "=" << column;
  std::cout << "; " << recognised.unmapped.size() << " not recognised (listed in the file)\n"
            << "next: usvid compare --suite real --data-dir "
            << (vessels.empty() ? std::string(".") : vessels.string()) << '\n';
}

}  // namespace

void AddInitTrackCommand(CLI::App& app) {
  auto o = std::make_shared<InitTrackOptions>();
  CLI::App* cmd = app.add_subcommand("init-track",
                                     "Start a vessel folder: a track.yaml from a log's header "
                                     "(docs/tracks.md), the log copied in");
  cmd->add_option("folder", o->folder, "The vessel folder, DIR/NAME (created if absent)")
      ->required();
  cmd->add_option("--data", o->data,
                  "The vessel's logs (CSV): the first one's header is read; each outside the "
                  "folder is copied into it")
      ->required();
  cmd->add_option("--vessel", o->vessel,
                  "A vessel file (docs/model.md#vessel-files) to copy in as vessel.yaml");
  cmd->add_flag("--force", o->force, "Write over a track.yaml already there");
  cmd->callback([o] { RunInitTrack(*o); });
}

}  // namespace usvid
