// ranks.h on MPI (-DUSVID_WITH_MPI=ON).
#include <mpi.h>

#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "harness/ranks.h"

namespace usvid {
namespace {

void Check(int code, const char* what) {
  if (code == MPI_SUCCESS) return;
  char text[MPI_MAX_ERROR_STRING];
  int length = 0;
  MPI_Error_string(code, text, &length);
  throw std::runtime_error(std::string("MPI: ") + what + ": " + std::string(text, length));
}

}  // namespace

RanksSession::RanksSession(int& argc, char**& argv) {
  int provided = 0;
  Check(MPI_Init_thread(&argc, &argv, MPI_THREAD_SERIALIZED, &provided), "MPI_Init_thread");
  // Errors come back as codes (Check), not as an abort from inside MPI.
  MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
}

RanksSession::~RanksSession() { MPI_Finalize(); }

namespace ranks {

int Rank() {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return rank;
}

int Size() {
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  return size;
}

std::string Broadcast(const std::string& text) {
  unsigned long long length = text.size();
  Check(MPI_Bcast(&length, 1, MPI_UNSIGNED_LONG_LONG, 0, MPI_COMM_WORLD), "MPI_Bcast");
  std::string out = Rank() == 0 ? text : std::string(length, '\0');
  Check(MPI_Bcast(out.data(), static_cast<int>(length), MPI_CHAR, 0, MPI_COMM_WORLD), "MPI_Bcast");
  return out;
}

std::vector<std::string> Gather(const std::string& text) {
  if (text.size() > static_cast<size_t>(INT32_MAX))
    throw std::runtime_error("MPI: a rank's results exceed 2 GiB");
  const int size = Size(), rank = Rank();
  int length = static_cast<int>(text.size());
  std::vector<int> lengths(rank == 0 ? size : 0), offsets(rank == 0 ? size : 0);
  Check(MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, MPI_COMM_WORLD),
        "MPI_Gather");
  std::string all;
  if (rank == 0) {
    long long total = 0;
    for (int r = 0; r < size; ++r) {
      offsets[r] = static_cast<int>(total);
      total += lengths[r];
    }
    if (total > INT32_MAX) throw std::runtime_error("MPI: the gathered results exceed 2 GiB");
    all.resize(static_cast<size_t>(total));
  }
  Check(MPI_Gatherv(text.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(),
                    MPI_CHAR, 0, MPI_COMM_WORLD),
        "MPI_Gatherv");
  std::vector<std::string> out;
  for (int r = 0; r < static_cast<int>(lengths.size()); ++r)
    out.push_back(all.substr(offsets[r], lengths[r]));
  return out;
}

void Abort(int code) {
  MPI_Abort(MPI_COMM_WORLD, code);
  std::exit(code);  // MPI_Abort does not return; this keeps [[noreturn]] honest
}

namespace {

constexpr int kAsk = 1, kGive = 2;

bool Serialized() {
  int level = MPI_THREAD_SINGLE;
  MPI_Query_thread(&level);
  return level >= MPI_THREAD_SERIALIZED;
}

}  // namespace

// Rank 0 owns the counter. Its own threads take from it directly; a thread on rank 0 answers the
// other ranks, whose threads ask one at a time (the mutex) until they are told "n": no more.
struct WorkQueue::State {
  size_t n = 0, next = 0;
  int rank = 0, size = 1;
  bool dealt = false;     // no MPI_THREAD_SERIALIZED: a fixed round-robin deal
  bool finished = false;  // ranks > 0: told there is no more
  std::mutex mutex;
  MPI_Comm comm = MPI_COMM_NULL;
  std::thread server;

  void Serve() {
    int asking = size - 1;  // ranks not yet told "no more"
    while (asking > 0) {
      unsigned long long request = 0;
      MPI_Request pending;
      MPI_Status status;
      MPI_Irecv(&request, 1, MPI_UNSIGNED_LONG_LONG, MPI_ANY_SOURCE, kAsk, comm, &pending);
      int arrived = 0;
      // Polled, not a blocking receive: OpenMPI would spin a core waiting.
      while (MPI_Test(&pending, &arrived, &status) == MPI_SUCCESS && !arrived)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
      unsigned long long reply = 0;
      {
        std::lock_guard lock(mutex);
        reply = next < n ? next++ : n;
      }
      if (reply == n) --asking;
      MPI_Send(&reply, 1, MPI_UNSIGNED_LONG_LONG, status.MPI_SOURCE, kGive, comm);
    }
  }
};

WorkQueue::WorkQueue(size_t n) : state_(std::make_unique<State>()) {
  State& s = *state_;
  s.n = n;
  s.rank = Rank();
  s.size = Size();
  s.dealt = !Serialized();
  if (s.dealt) {
    s.next = static_cast<size_t>(s.rank);
    return;
  }
  Check(MPI_Comm_dup(MPI_COMM_WORLD, &s.comm), "MPI_Comm_dup");
  if (s.rank == 0 && s.size > 1) s.server = std::thread([&s] { s.Serve(); });
}

WorkQueue::~WorkQueue() {
  State& s = *state_;
  if (s.server.joinable()) {
    {
      // Leaving early (an exception): the other ranks are told there is no more.
      std::lock_guard lock(s.mutex);
      s.next = s.n;
    }
    s.server.join();
  }
  if (s.comm != MPI_COMM_NULL) MPI_Comm_free(&s.comm);
}

std::optional<size_t> WorkQueue::Next() {
  State& s = *state_;
  std::lock_guard lock(s.mutex);
  if (s.dealt) {
    if (s.next >= s.n) return std::nullopt;
    const size_t k = s.next;
    s.next += static_cast<size_t>(s.size);
    return k;
  }
  if (s.rank == 0) {
    if (s.next == s.n) return std::nullopt;
    return s.next++;
  }
  if (s.finished) return std::nullopt;
  unsigned long long request = 0, reply = 0;
  if (MPI_Send(&request, 1, MPI_UNSIGNED_LONG_LONG, 0, kAsk, s.comm) != MPI_SUCCESS ||
      MPI_Recv(&reply, 1, MPI_UNSIGNED_LONG_LONG, 0, kGive, s.comm, MPI_STATUS_IGNORE) !=
          MPI_SUCCESS)
    Abort(1);  // the rank cannot reach rank 0: nothing sensible is left to do
  if (reply >= s.n) {
    s.finished = true;
    return std::nullopt;
  }
  return static_cast<size_t>(reply);
}

}  // namespace ranks
}  // namespace usvid
