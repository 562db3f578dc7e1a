// USVID_CHECK (core/check.h): a broken internal invariant stops the program with the condition,
// the file:line and the reason on stderr; a kept one costs nothing visible.
#include <gtest/gtest.h>

#include "core/check.h"

namespace usvid {
namespace {

TEST(CheckDeathTest, NamesTheConditionTheLineAndTheReason) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  const int rows = 3;
  EXPECT_DEATH(USVID_CHECK(rows == 4, "a channel as long as t"),
               "internal error at .*check_test.cc:[0-9]+: rows == 4 failed: a channel as long as t");
  EXPECT_DEATH(USVID_UNREACHABLE("every case handled"), "unreachable failed: every case handled");
}

TEST(CheckTest, AKeptInvariantGoesOn) {
  int evaluated = 0;
  USVID_CHECK(++evaluated == 1, "evaluated once");
  EXPECT_EQ(evaluated, 1);
}

}  // namespace
}  // namespace usvid
