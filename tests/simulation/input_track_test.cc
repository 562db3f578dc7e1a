// InputTrack (zero-order hold): the command in force at t is the last sample at or before t, the
// first before t_0, whatever the order of the lookups; a lookup writes nothing into the track,
// so threads sharing one track each get what they would get alone.
#include "simulation/input_track.h"

#include <gtest/gtest.h>

#include <random>
#include <thread>
#include <vector>

namespace usvid {
namespace {

// Irregular sample times, each sample's value its index.
InputTrack Track(int n) {
  InputTrack track(1);
  double t = 0.0;
  std::mt19937_64 rng(7);
  for (int k = 0; k < n; ++k) {
    track.Append(t, std::vector<double>{static_cast<double>(k)});
    t += std::uniform_real_distribution<double>(0.01, 0.2)(rng);
  }
  return track;
}

// The reference: a linear scan.
double InForce(const InputTrack& track, double t) {
  size_t k = 0;
  while (k + 1 < track.size() && track.time(k + 1) <= t) ++k;
  return static_cast<double>(k);
}

TEST(InputTrackTest, AnyOrderOfLookupsGivesTheSampleInForce) {
  const InputTrack track = Track(500);
  const double end = track.time(track.size() - 1);
  std::mt19937_64 rng(3);
  InputTrack::Cursor cursor;
  double t = -1.0;
  for (int i = 0; i < 5000; ++i) {
    // Mostly small steps forward (a rollout), sometimes a jump either way.
    const double r = std::uniform_real_distribution<double>(0, 1)(rng);
    t = r < 0.9 ? t + 0.03 : std::uniform_real_distribution<double>(-1.0, end + 1.0)(rng);
    ASSERT_EQ(*track.At(t, cursor), InForce(track, t)) << "t=" << t;
    ASSERT_EQ(*track.At(t), InForce(track, t)) << "t=" << t;
  }
  // Exactly on a sample: that sample.
  EXPECT_EQ(*track.At(track.time(7), cursor), 7.0);
}

TEST(InputTrackTest, ThreadsSharingATrackEachGetWhatTheyWouldAlone) {
  const InputTrack track = Track(2000);
  const double end = track.time(track.size() - 1);
  auto sweep = [&](double step, std::vector<double>& out) {
    InputTrack::Cursor cursor;
    for (double t = 0.0; t < end; t += step) {
      double u = 0.0;
      track.DelayedMean(t, step, 0.05, {}, &u, cursor);
      out.push_back(u);
    }
  };
  std::vector<double> alone_a, alone_b, a, b;
  sweep(0.011, alone_a);
  sweep(0.037, alone_b);
  std::thread ta([&] { sweep(0.011, a); });
  std::thread tb([&] { sweep(0.037, b); });
  ta.join();
  tb.join();
  EXPECT_EQ(a, alone_a);
  EXPECT_EQ(b, alone_b);
}

}  // namespace
}  // namespace usvid
