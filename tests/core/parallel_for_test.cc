// ParallelFor (core/parallel_for.h): every index runs once, and inside a team of threads a
// thread that has run out of its own work takes indices of another's loop, which is what lets a
// suite's idle threads share its last long fit.
#include "core/parallel_for.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <chrono>
#include <set>
#include <thread>
#include <vector>

namespace usvid {
namespace {

TEST(ParallelForTest, OutsideATeamEveryIndexRunsOnce) {
  std::vector<int> runs(100, 0);
  ParallelFor(100, 2, [&](int i) { runs[i] += 1; });
  for (int i = 0; i < 100; ++i) EXPECT_EQ(runs[i], 1) << i;
}

// A team of two: thread 0 runs a loop of slow pieces, thread 1 has nothing of its own and waits
// at the team's end. Both run pieces, each piece once, and the results are the pieces' own.
TEST(ParallelForTest, InATeamAnIdleThreadTakesPieces) {
  if (omp_get_max_threads() < 2 && omp_get_num_procs() < 2) GTEST_SKIP() << "one core";
  std::vector<int> thread_of(16, -1);
  std::vector<double> square(16, 0.0);
#pragma omp parallel num_threads(2)
  {
    if (omp_get_thread_num() == 0 && omp_get_num_threads() == 2)
      ParallelFor(16, 1, [&](int i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        thread_of[i] = omp_get_thread_num();
        square[i] = static_cast<double>(i) * i;
      });
  }
  std::set<int> threads(thread_of.begin(), thread_of.end());
  EXPECT_EQ(threads, (std::set<int>{0, 1}));
  for (int i = 0; i < 16; ++i) EXPECT_EQ(square[i], static_cast<double>(i) * i);
}

}  // namespace
}  // namespace usvid
