// ranks.h without MPI: one process.
#include <cstdlib>
#include <mutex>

#include "harness/ranks.h"

namespace usvid {

RanksSession::RanksSession(int&, char**&) {}
RanksSession::~RanksSession() = default;

namespace ranks {

int Rank() { return 0; }
int Size() { return 1; }
std::string Broadcast(const std::string& text) { return text; }
std::vector<std::string> Gather(const std::string& text) { return {text}; }
void Abort(int code) { std::exit(code); }

struct WorkQueue::State {
  std::mutex mutex;
  size_t next = 0, n = 0;
};

WorkQueue::WorkQueue(size_t n) : state_(std::make_unique<State>()) { state_->n = n; }
WorkQueue::~WorkQueue() = default;

std::optional<size_t> WorkQueue::Next() {
  std::lock_guard lock(state_->mutex);
  if (state_->next == state_->n) return std::nullopt;
  return state_->next++;
}

}  // namespace ranks
}  // namespace usvid
