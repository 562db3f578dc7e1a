#include "harness/cell_store.h"

#include <cstdio>
#include <filesystem>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/json_file.h"

namespace usvid {
namespace fs = std::filesystem;

nlohmann::json CellJson(const FitJob& fit, const std::vector<ResultRow>& rows) {
  // The rows of a cell share its one model: kept once.
  nlohmann::json cell = {{"job", fit.Id()},
                         {"model", rows.empty() ? nlohmann::json() : rows.front().model},
                         {"rows", nlohmann::json::array()}};
  for (const ResultRow& r : rows) cell["rows"].push_back(r.ToCellJson());
  return cell;
}

std::vector<ResultRow> CellRows(const nlohmann::json& cell, const std::string& job_id,
                                const std::string& source) {
  try {
    if (cell.at("job").get<std::string>() != job_id)
      throw InputError(source + ": holds job '" + cell.at("job").get<std::string>() +
                       "', expected '" + job_id + "'");
    std::vector<ResultRow> rows;
    for (const nlohmann::json& r : cell.at("rows")) {
      rows.push_back(ResultRow::FromCellJson(r));
      rows.back().model = cell.at("model");
    }
    return rows;
  } catch (const nlohmann::json::exception& e) {
    throw InputError(source + ": not a usvid cell (" + e.what() + ")");
  }
}

CellStore::CellStore(const std::string& out_dir, const Suite& suite, const std::string& build,
                     bool fresh)
    : dir_(out_dir + "/cells") {
  EnsureOutputDirectory(dir_);
  const std::string owner_file = dir_ + "/suite.json";
  const nlohmann::json mine = {{"suite", SuiteToJson(suite)}, {"usvid_build", build}};
  std::error_code ec;
  if (fresh) {
    for (const auto& entry : fs::directory_iterator(dir_, ec))
      if (entry.path().filename().string().starts_with("cell-")) fs::remove(entry.path(), ec);
  } else if (fs::exists(owner_file, ec)) {
    const nlohmann::json theirs = ReadJsonFile(owner_file);
    if (!theirs.is_object() || !theirs.contains("suite") || !theirs.contains("usvid_build") ||
        !theirs["usvid_build"].is_string())
      throw InputError(owner_file + ": not a usvid cells record; --fresh to discard it");
    if (theirs["suite"] != mine["suite"])
      throw InputError(dir_ + ": holds the cells of another suite; give another --out, or " +
                       "--fresh to discard them");
    if (theirs["usvid_build"] != build)
      throw InputError(dir_ + ": holds cells of another usvid build (" +
                       theirs["usvid_build"].get<std::string>() + ", this is " + build +
                       "); give another --out, or --fresh to discard them");
  }
  WriteJsonFile(owner_file, mine);
}

CellStore::CellStore(const std::string& out_dir) : dir_(out_dir + "/cells") {
  EnsureOutputDirectory(dir_);
}

std::string CellStore::CellFile(size_t job) const {
  char name[32];
  std::snprintf(name, sizeof name, "cell-%05zu.json", job);
  return dir_ + "/" + name;
}

std::map<size_t, std::vector<ResultRow>> CellStore::Load(const std::vector<FitJob>& jobs) const {
  std::map<size_t, std::vector<ResultRow>> done;
  for (size_t j = 0; j < jobs.size(); ++j) {
    const std::string file = CellFile(j);
    std::error_code ec;
    if (!fs::exists(file, ec)) continue;
    done[j] = CellRows(ReadJsonFile(file), jobs[j].Id(), file);
  }
  return done;
}

void CellStore::Save(size_t job, const FitJob& fit, const std::vector<ResultRow>& rows) const {
  // An external command's failed fit is not kept: the command lies outside the build that the
  // cells are tied to, and may be fixed (or its timeout pass) before the run is resumed.
  if (fit.method.method == kExternalMethod && !rows.empty() && rows.front().model.is_null()) return;
  WriteFileAtomically(CellFile(job), CellJson(fit, rows).dump() + "\n");
}

}  // namespace usvid
