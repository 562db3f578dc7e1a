// The weight of each shooting segment in a refit of several records at once (identify --data
// a.csv,b.csv, a suite's list of training files) with `"record_weights": "equal"`: every record
// weighs the same in all, whatever its length.
//
// Why. With every segment weighed alike, a record counts by its length: on Esso Osaka the two
// 12-minute random runs held half of the rows of the eight runs refit was trained on, and the
// fit bent to them, where the unlogged thrusters and the wind push the model. Weighed alike,
// the held-out zig-zags' r fit rose on three of four and the random runs' a little, while the
// turning circles widened slightly (docs/real-data.md#refit-record-weights); so it is an
// option, not the default.
#pragma once

#include <Eigen/Core>
#include <utility>
#include <vector>

namespace usvid {

// One weight per segment [first, last] (rows): 1 / (records * that record's segments), scaled so
// that the weights average 1, where a segment belongs to the record (core/records.h's
// RecordStarts) its first row is in. One record: every weight 1.
std::vector<double> RecordWeights(
    const std::vector<std::pair<Eigen::Index, Eigen::Index>>& segments,
    const std::vector<long>& record_starts);

}  // namespace usvid
