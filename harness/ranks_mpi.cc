// ranks.h on MPI (-DUSVID_WITH_MPI=ON).
#include <mpi.h>

#include <cstdint>
#include <cstdlib>
#include <stdexcept>

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
  Check(MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided), "MPI_Init_thread");
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
  Check(MPI_Bcast(out.data(), static_cast<int>(length), MPI_CHAR, 0, MPI_COMM_WORLD),
        "MPI_Bcast");
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

}  // namespace ranks
}  // namespace usvid
