// The processes a run is spread over: the MPI ranks of `mpirun -n N usvid ...` when usvid is
// built with -DUSVID_WITH_MPI=ON, otherwise one. Every call is collective where MPI's would be
// (Broadcast, Gather: all ranks call them in the same order). Built without MPI, Rank() is 0,
// Size() is 1 and the collectives return their argument: the default build has no MPI at all.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace usvid {

// Starts MPI for the life of main (a no-op without MPI). Threads: OpenMP inside a rank, and MPI
// called by one thread at a time (MPI_THREAD_SERIALIZED).
class RanksSession {
 public:
  RanksSession(int& argc, char**& argv);
  ~RanksSession();
  RanksSession(const RanksSession&) = delete;
  RanksSession& operator=(const RanksSession&) = delete;
};

namespace ranks {

int Rank();
int Size();
// Rank 0's `text`, on every rank.
std::string Broadcast(const std::string& text);
// On rank 0: every rank's `text`, in rank order. Elsewhere: empty.
std::vector<std::string> Gather(const std::string& text);
// Ends every rank with exit code `code` (a failure on one rank must not leave the others
// waiting in a collective). Without MPI: std::exit(code).
[[noreturn]] void Abort(int code);

// Hands out 0, 1, ..., n-1, each once over all ranks, to whichever thread of whichever rank asks
// first: work goes where a core is free, not where a fixed deal put it. Every rank constructs
// and destroys its queue at the same point (collective). Next() is thread-safe.
// With MPI, rank 0 serves the other ranks from a thread that polls every 1 ms; an MPI without
// MPI_THREAD_SERIALIZED gets a fixed round-robin deal instead.
class WorkQueue {
 public:
  explicit WorkQueue(size_t n);
  ~WorkQueue();
  WorkQueue(const WorkQueue&) = delete;
  WorkQueue& operator=(const WorkQueue&) = delete;
  std::optional<size_t> Next();

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace ranks
}  // namespace usvid
