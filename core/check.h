// Internal invariants (Drake's DRAKE_DEMAND): USVID_CHECK(condition, message) aborts, after
// printing the condition, file:line and the message on stderr, when the condition is false.
// For what the program itself guarantees, never for user input: bad input throws InputError
// (core/error.h) and exits 2. Active in every build type; the condition is evaluated once.
#pragma once

namespace usvid::internal {

[[noreturn]] void CheckFailed(const char* condition, const char* file, int line,
                              const char* message);

}  // namespace usvid::internal

#define USVID_CHECK(condition, message)                                            \
  do {                                                                             \
    if (!(condition)) ::usvid::internal::CheckFailed(#condition, __FILE__, __LINE__, \
                                                     message);                     \
  } while (false)

// An unreachable branch: aborts with file:line and the message.
#define USVID_UNREACHABLE(message) \
  ::usvid::internal::CheckFailed("unreachable", __FILE__, __LINE__, message)
