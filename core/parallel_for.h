// ParallelFor: independent pieces of one fit (the hybrid's proposed terms, diagnose's candidate
// effects) run on whatever threads are free.
//
// A suite runs its cells on a team of OpenMP threads (harness/run_suite.cc), one cell a thread,
// so a parallel loop inside a cell would get a team of one (nested parallelism is off) and the
// last long cell would run alone while the other threads wait at the team's end. Inside such a
// team, ParallelFor makes each index a task of that team instead: a thread that has run out of
// cells waits at the team's end barrier, and a thread waiting at a barrier runs the team's
// pending tasks. Outside a team it is a parallel loop on `threads` threads.
//
// The libraries that use it link OpenMP::OpenMP_CXX (core itself needs no OpenMP).
//
// body(i) must not throw (an exception may not leave an OpenMP task or loop) and must write only
// to its own index's results: then the results do not depend on which thread ran which index.
#pragma once

#include <omp.h>

#include <algorithm>

namespace usvid {

template <class Body>
void ParallelFor(int n, int threads, const Body& body) {
  if (omp_in_parallel()) {
#pragma omp taskloop grainsize(1) default(shared)
    for (int i = 0; i < n; ++i) body(i);
    return;
  }
#pragma omp parallel for schedule(dynamic) num_threads(std::max(1, threads))
  for (int i = 0; i < n; ++i) body(i);
}

}  // namespace usvid
