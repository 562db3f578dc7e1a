// The zig-zag test's figures of merit (ITTC 7.5-04-02-01) read from any record, measured or
// simulated: the rudder is executed where the first full-angle order held until the heading
// has turned by B begins to move, more than 1 deg (metrics/maneuver_execute.h: a real log's
// hand steering before the test is skipped), else where it first moves more than 1 deg from its
// initial value (heading psi0 at the execute); it is reversed where it crosses zero on its way to
// the other side's leg (half its angle there: a flicker about zero reverses nothing); the overshoot
// after each reversal is how far the heading goes beyond the threshold B (from the base course)
// in the direction it was turning at the reversal, before the next one.
//
// The base course is the heading the test's reversals were ordered about, read from the record:
// each reversal is ordered where the rudder leaves its full angle, at base + B on one side and
// base - B on the other, so the midpoint of two successive orders' headings is the base course
// (the helm's reaction beyond B falls out, being the same both sides). It is not always the
// heading at the execute: a ship a little off the ordered course at the execute reads overshoots
// that differ by twice that offset between port and starboard (MARIN's KVLCC2 zig-zags, measured
// in docs/real-data.md#kvlcc2-base-course). The
// base course is psi0 (ITTC's) unless the orders give another clearly: at least one pair, an
// offset beyond the orders' resolution (a sample's turn), and a clean test: the orders'
// distances from the base course span at most 1 deg and lie between B - 0.5 and B + 2 deg (a
// helm that reacts late, by as much each time). Reversals ordered by hand at scattered headings
// (a pond in wind) say no base course but the execute's. Works with either rudder sign convention
// (the turning direction is read from the heading). A heading that wraps at +-pi, as logs write it,
// is unwrapped first (core/angles.h), and a noisy one smoothed (metrics/criteria_smoothing.h): the
// furthest raw sample would be a noise peak.
#pragma once

#include <string>
#include <vector>

#include "core/dataset.h"

namespace usvid {

struct ZigzagResponse {
  double execute_s = 0.0;             // time of the first rudder execution
  int first_turn = 0;                 // +1 starboard (psi grows), -1 port
  std::vector<double> reversal_s;     // rudder zero crossings after the execution
  std::vector<double> overshoot_deg;  // after each reversal (the last may be cut short)
  double base_offset_deg = 0.0;       // the base course less psi0
};

// The heading check B of a zig-zag record, read from the record (B is not assumed equal to the
// rudder angle A: HSVA's KVLCC2 tests run 20/10, 30/5 and 10/1). Each reversal is ordered as the
// heading reaches base + B or base - B, at the last sample of a leg at full angle (the order);
// half the heading swing between two successive orders is B plus the helm's lag past it, the
// same both sides, whatever the base course. `order_deg` is the median of those half swings
// (with a single reversal, its order's heading from the execute's). `check_deg` is A when the
// orders lie within kCheckNearRudderDeg of it (the usual 10/10 and 20/20; a hand-steered test
// orders a few degrees early or late: the Esso Osaka pond's 30/30 of 13:50 at 27.9 deg), else
// the nearest preferred check (1, then every 5 deg): MARIN's KVLCC2 orders lie 0.6
// deg past B = 20, a fast vessel's up to half a sample's turn (2.3 deg) past it. 0 when the record
// holds no order. `rudder_deg`: A, for what counts as full angle (within max(1 deg, 10 %)); 0:
// the record's largest.
inline constexpr double kCheckNearRudderDeg = 3.0;
struct ZigzagCheckReading {
  double check_deg = 0.0;  // B read, or 0
  double order_deg = 0.0;  // the orders' median half swing
  int orders = 0;          // reversals ordered from full angle
  // A zig-zag orders every reversal at the same heading off its base course, so its half
  // swings agree: on the shared real zig-zags within 2.6 deg of their median, but for one early
  // order of a hand-steered 15/15 (Esso Osaka, 13:29: 6.8, 14.7 and 15.0 deg); a rudder that
  // switches at random (Esso Osaka's random runs, held at +-35 deg to both sides as a 35/B
  // zig-zag is) swings 0.2 to 29 deg between its reversals.
  int half_swings = 0;  // orders between two legs at full angle
  int agreeing = 0;     // of them, within kCheckAgreementDeg (or a quarter) of their median
  double first_order_deg = 0.0;  // the first order's heading from the execute's (0: none)
  // Whether the orders agree as a zig-zag's do: at least two thirds of two or more half swings
  // agree; one half swing agrees so with the first order's heading from the execute's (both B
  // and the helm's lag); with no half swing there is nothing to tell.
  bool Consistent() const;
};
inline constexpr double kCheckAgreementDeg = 2.5;
ZigzagCheckReading ReadZigzagCheck(const Dataset& data, const std::string& heading = "psi",
                                   const std::string& rudder = "delta", double rudder_deg = 0.0);

// Throws InputError (naming the data's file) when a channel is missing or the rudder never
// moves.
// `rudder_deg`: the test's rudder angle A, for finding the execute; 0 takes the record's
// largest; below 0, the execute is the first movement (a simulated run, which starts at its
// lead-in).
ZigzagResponse AnalyseZigzag(const Dataset& data, double threshold_deg,
                             const std::string& heading = "psi",
                             const std::string& rudder = "delta", double rudder_deg = 0.0);

}  // namespace usvid
