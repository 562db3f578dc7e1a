// The execute of a zig-zag or turning test (metrics/maneuver_execute.h): in a simulated record
// it is the first rudder movement; in a real log, where the operator steers by hand before the
// test, it is the start of the first full-angle order held until the heading has turned by the
// test's angle. The command and heading below are built sample by sample: the heading turns
// 1 deg a sample while the rudder is at full angle, and drifts 0.1 deg a sample otherwise.
#include "metrics/maneuver_execute.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace usvid {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

struct Record {
  std::vector<double> command, heading;
  void Hold(double deg, int samples) {
    for (int i = 0; i < samples; ++i) Add(deg);
  }
  // The rudder moved to `deg` at 5 deg a sample.
  void MoveTo(double deg) {
    double at = command.empty() ? 0.0 : command.back() / kDeg;
    while (std::abs(deg - at) > 1e-9) {
      at += std::clamp(deg - at, -5.0, 5.0);
      Add(at);
    }
  }
  void Add(double deg) {
    const double before = heading.empty() ? 0.0 : heading.back();
    const bool full = std::abs(deg) >= 19.9;
    heading.push_back(before + (full ? (deg > 0 ? 1.0 : -1.0) : 0.1) * kDeg);
    command.push_back(deg * kDeg);
  }
  long Execute(double turn_deg = 20.0) const {
    return FindExecute(command, heading, kDeg, turn_deg * kDeg);
  }
};

TEST(ManeuverExecuteTest, ASimulatedRecordIsExecutedAtItsFirstRudderMovement) {
  Record r;
  r.Hold(0.0, 50);  // the lead-in
  r.MoveTo(20.0);   // samples 50 (5 deg), 51 (10), 52 (15), 53 (20)
  r.Hold(20.0, 40);
  EXPECT_EQ(r.Execute(), 50);
}

TEST(ManeuverExecuteTest, HandSteeringBeforeTheTestIsSkipped) {
  Record r;
  r.Hold(0.0, 10);
  for (int i = 0; i < 5; ++i) {  // steering by hand while the ship gathers way
    r.MoveTo(5.0);
    r.Hold(5.0, 5);
    r.MoveTo(-5.0);
    r.Hold(-5.0, 5);
  }
  r.MoveTo(20.0);  // a full-angle order not held until the heading has turned 20 deg
  r.Hold(20.0, 5);
  r.MoveTo(0.0);
  r.Hold(0.0, 20);
  const long test = static_cast<long>(r.command.size());
  r.MoveTo(-20.0);  // the test: held until the heading has turned 20 deg (to port here)
  r.Hold(-20.0, 30);
  EXPECT_EQ(r.Execute(), test);
}

TEST(ManeuverExecuteTest, AnOrderNeverHeldLongEnoughIsNoExecute) {
  Record r;
  r.Hold(0.0, 10);
  r.MoveTo(20.0);
  r.Hold(20.0, 10);  // 14 deg of turn with the ramp, short of 20
  r.MoveTo(0.0);
  r.Hold(0.0, 10);
  EXPECT_EQ(r.Execute(), -1);
  EXPECT_EQ(r.Execute(10.0), 10);  // a 10 deg test would count it
}

}  // namespace
}  // namespace usvid
