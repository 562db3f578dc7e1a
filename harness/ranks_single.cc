// ranks.h without MPI: one process.
#include <cstdlib>

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

}  // namespace ranks
}  // namespace usvid
