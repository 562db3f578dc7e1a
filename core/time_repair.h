// Repairs the time column of a foreign log, never silently: the returned report says what was
// done, for the importer to print.
//  - DropNonIncreasingRows: drops every row whose t is not greater than the last kept t.
//  - RebuildRoundedTime: for a fixed-rate logger whose stamps were printed with few significant
//    digits (so consecutive rows repeat a stamp), fits t = t_0 + i dt (t_0 the first stamp) by
//    weighted least squares and, when every stamp lies within its rounding step (or one dt) of that
//    line, replaces the stamps by it; otherwise falls back to dropping non-increasing rows.
#pragma once

#include <string>

#include "core/dataset.h"

namespace usvid {

struct TimeRepairReport {
  int rows_in = 0;
  int repeated = 0;        // rows whose stamp equals the previous one
  int went_back = 0;       // rows whose stamp is below the previous one
  int dropped = 0;         // rows removed
  bool rebuilt = false;    // stamps replaced by a uniform grid
  double dt = 0.0;         // of the rebuilt grid [s]
  double max_shift = 0.0;  // largest |new - old| stamp [s]

  bool Changed() const { return dropped > 0 || rebuilt; }
  std::string Summary() const;
};

TimeRepairReport DropNonIncreasingRows(Dataset& data);
TimeRepairReport RebuildRoundedTime(Dataset& data, int significant_digits);

}  // namespace usvid
