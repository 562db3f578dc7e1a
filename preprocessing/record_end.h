// Where a test's record ends: the last row at which an actuator still ran. A free-running model
// test ends when its propeller is stopped; what a log holds after that is the recovery, and on
// the Esso Osaka model it is driven by bow and stern thrusters that are not logged: the zig-zag
// of 31 Jul 13:04 swings its yaw rate by 0.15 rad/s in the 13 s after the propeller stopped,
// with the rudder amidships, more than anywhere in the test. No model of the logged inputs can
// follow that, and a free run scored over it is scored on the thrusters
// (docs/data.md#the-end-of-a-test).
#pragma once

#include <string>

#include "core/dataset.h"

namespace usvid {

struct RecordEnd {
  double t_end = 0.0;      // time of the last row kept [s]
  double dropped_s = 0.0;  // seconds of record dropped after it
  int dropped_rows = 0;
};

// The last row at which |channel| is above 1 % of its largest magnitude in the record ("still
// running": a noisy zero reads as stopped, an idling propeller as running). Throws InputError
// naming the data's file when the channel is missing, has empty cells or never runs.
RecordEnd FindRecordEnd(const Dataset& data, const std::string& channel);

// Drops the rows after FindRecordEnd's last running row.
RecordEnd EndAtStop(Dataset& data, const std::string& channel);

// "ended where n stopped, at t = 127.1 s: 13.1 s (131 rows) dropped" for a report.
std::string DescribeRecordEnd(const RecordEnd& end, const std::string& channel);

}  // namespace usvid
