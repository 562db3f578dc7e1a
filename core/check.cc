#include "core/check.h"

#include <cstdio>
#include <cstdlib>

namespace usvid::internal {

void CheckFailed(const char* condition, const char* file, int line, const char* message) {
  std::fprintf(stderr, "usvid: internal error at %s:%d: %s failed: %s\n", file, line, condition,
               message);
  std::fflush(stderr);
  std::abort();
}

}  // namespace usvid::internal
