#include "harness/distributed_run.h"

#include <map>
#include <nlohmann/json.hpp>
#include <optional>

#include "core/error.h"
#include "harness/cell_store.h"
#include "harness/ranks.h"
#include "harness/run_suite.h"

namespace usvid {

DistributedRun RunSuiteDistributed(const Suite& suite, const std::string& out_dir,
                                   const DistributedRunOptions& options,
                                   const std::function<void(const std::string&)>& progress) {
  const std::vector<FitJob> jobs = FitJobs(suite);
  const int rank = ranks::Rank(), size = ranks::Size();
  DistributedRun run;
  run.cells = jobs.size();

  // Rank 0 alone opens the store (a fresh start, the suite check) and decides which cells are
  // left; the others learn it by broadcast, whatever their view of the file system.
  std::optional<CellStore> store;
  std::map<size_t, std::vector<ResultRow>> finished;
  nlohmann::json plan = {{"error", ""}, {"pending", nlohmann::json::array()}};
  if (rank == 0) {
    try {
      store.emplace(out_dir, suite, options.build, options.fresh);
      finished = store->Load(jobs);
      for (size_t j = 0; j < jobs.size(); ++j)
        if (!finished.contains(j)) plan["pending"].push_back(j);
    } catch (const InputError& e) {
      plan["error"] = e.what();
    }
  }
  plan = nlohmann::json::parse(ranks::Broadcast(plan.dump()));
  if (!plan["error"].get<std::string>().empty()) throw InputError(plan["error"].get<std::string>());
  if (rank != 0) store.emplace(out_dir);
  run.resumed = jobs.size() - plan["pending"].size();
  if (rank == 0 && progress && run.resumed > 0)
    progress("resuming: " + std::to_string(run.resumed) + " of " + std::to_string(jobs.size()) +
             " cells are in " + store->Directory() + " and are not run again");

  // The cells left go to whichever thread of whichever rank is free (ranks::WorkQueue).
  const std::vector<size_t> pending =
      SlowestFirst(jobs, plan["pending"].get<std::vector<size_t>>());
  const std::string who = size > 1 ? "rank " + std::to_string(rank) + ": " : "";
  size_t count = 0;
  std::map<size_t, std::vector<ResultRow>> mine;
  {
    ranks::WorkQueue queue(pending.size());
    mine = RunCells(
        suite, jobs, options.threads,
        [&]() -> std::optional<size_t> {
          const std::optional<size_t> k = queue.Next();
          if (!k) return std::nullopt;
          return pending[*k];
        },
        [&](size_t j, const std::vector<ResultRow>& rows) {
          store->Save(j, jobs[j], rows);
          ++count;
          if (progress) progress(who + CellProgress(count, pending.size(), jobs[j], rows));
        });
  }

  // Rank 0 gathers every rank's cells as text and puts all rows in job order.
  nlohmann::json sent = nlohmann::json::array();
  for (const auto& [j, rows] : mine)
    sent.push_back({{"index", j}, {"cell", CellJson(jobs[j], rows)}});
  const std::vector<std::string> received = ranks::Gather(sent.dump());
  if (rank != 0) return run;
  for (const std::string& text : received)
    for (const nlohmann::json& c : nlohmann::json::parse(text)) {
      const size_t j = c.at("index").get<size_t>();
      finished[j] = CellRows(c.at("cell"), jobs.at(j).Id(), "a rank's cell");
    }
  // This rank's own cells give their rows the free runs and replays the report draws (in memory
  // only).
  for (const auto& [j, rows] : mine)
    for (size_t i = 0; i < rows.size() && i < finished[j].size(); ++i) {
      finished[j][i].free_run = rows[i].free_run;
      finished[j][i].replay = rows[i].replay;
    }
  for (auto& [j, rows] : finished) run.rows.insert(run.rows.end(), rows.begin(), rows.end());
  return run;
}

}  // namespace usvid
