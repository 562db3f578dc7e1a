// Which build of usvid is running: a hash of the executable's own bytes (/proc/self/exe).
// Results kept for resuming a run (harness/cell_store.h) are only reused by the same build, so
// a rebuilt usvid never mixes its numbers with an older one's.
#pragma once

#include <string>

namespace usvid {

// 16 hex digits; "unknown" where the executable cannot be read.
std::string ExecutableIdentity();

}  // namespace usvid
