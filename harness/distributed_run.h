// A comparison run that survives being killed and spreads over MPI ranks: the cells already in
// OUT/cells (cell_store.h) are taken as they are, and the rest go one at a time to whichever
// thread of whichever rank is free (ranks::WorkQueue), each saved as it finishes.
// Rank 0 gathers the rows and returns them in job order, the same rows a single process gives:
// each cell depends only on its seed. A cell whose fit fails is a row saying why, on any rank.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "harness/result_row.h"
#include "harness/suite.h"

namespace usvid {

struct DistributedRunOptions {
  int threads = 0;                // OpenMP threads per rank (0: OpenMP's default, OMP_NUM_THREADS)
  bool fresh = false;             // run every cell again, ignoring OUT/cells
  std::string build = "unknown";  // the usvid build (core/executable_identity.h)
};

struct DistributedRun {
  std::vector<ResultRow> rows;    // rank 0: every row in job order; other ranks: empty
  size_t cells = 0, resumed = 0;  // cells in the suite, and those taken from OUT/cells
};

DistributedRun RunSuiteDistributed(const Suite& suite, const std::string& out_dir,
                                   const DistributedRunOptions& options,
                                   const std::function<void(const std::string&)>& progress = {});

}  // namespace usvid
