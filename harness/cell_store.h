// The finished cells of a comparison, kept in OUT/cells/ so that a killed or failed run can be
// resumed: `usvid compare --out OUT` run again skips every cell already there. A cell is one fit
// job (suite.h) with its rows on every test maneuver; each is written whole (atomic_file.h) the
// moment it finishes, as cell-<job index>.json holding the job's id and its rows, models included.
// OUT/cells/suite.json names the suite and the usvid build (core/executable_identity.h) the
// cells belong to: cells of another suite or another build are an error, never silently mixed
// into the results.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "harness/result_row.h"
#include "harness/suite.h"

namespace usvid {

class CellStore {
 public:
  // Opens OUT/cells for `suite` run by usvid build `build`, creating it. `fresh`: forget the
  // cells already there. Throws InputError when OUT/cells belongs to another suite or build
  // (unless fresh).
  CellStore(const std::string& out_dir, const Suite& suite, const std::string& build, bool fresh);
  // The store another rank opened, to save cells into (an MPI rank on a shared file system).
  explicit CellStore(const std::string& out_dir);

  // The finished cells: job index -> rows. Throws InputError naming a cell file that cannot be
  // read or belongs to another job.
  std::map<size_t, std::vector<ResultRow>> Load(const std::vector<FitJob>& jobs) const;
  // Thread-safe for different jobs. An external method's failed fit is not saved, so that a
  // resumed run tries its command again.
  void Save(size_t job, const FitJob& fit, const std::vector<ResultRow>& rows) const;

  const std::string& Directory() const { return dir_; }

 private:
  std::string CellFile(size_t job) const;
  std::string dir_;
};

// A cell as JSON (what Save writes and MPI ranks exchange): {"job": id, "model": the model its
// rows share, "rows": [...]}, and
// its rows back, checked against the job's id (InputError naming `source` otherwise).
nlohmann::json CellJson(const FitJob& fit, const std::vector<ResultRow>& rows);
std::vector<ResultRow> CellRows(const nlohmann::json& cell, const std::string& job_id,
                                const std::string& source);

}  // namespace usvid
