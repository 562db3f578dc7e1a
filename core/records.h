// Several records of one vessel as one Dataset, for a joint fit (`identify --data a.csv,b.csv`,
// a suite's list of training files): each record's time is shifted so that it starts
// kRecordGapS seconds after the one before it ends. That gap is longer than any segment,
// horizon or interpolation a method runs, and a gap to every step that looks for one
// (core/stretches.h), so nothing is differentiated or simulated across it; preprocessing
// smooths and differentiates each record on its own (docs/data.md#several-records-and-gaps).
#pragma once

#include <string>
#include <vector>

#include "core/dataset.h"

namespace usvid {

inline constexpr double kRecordGapS = 1000.0;

// The records joined in order. Keeps the channels that every record has; those that only some
// have are appended to `dropped` (may be null). Metadata: the first record's, with "records"
// (how many) and "source" (each record's source, joined by ", "), and without "maneuver" (a
// record's own, F.record.json: no maneuver of the joined ones). One record comes back as it
// is. Throws InputError for an empty list.
Dataset JoinRecords(std::vector<Dataset> records, std::vector<std::string>* dropped = nullptr);

// The first row of each record in `t`, a joined record's times: row 0, then every row that
// follows a jump of at least half kRecordGapS (a log's own gaps, GPS dropouts of seconds, are
// not records). One record: {0}; no rows: {}.
std::vector<long> RecordStarts(const Eigen::Ref<const Eigen::VectorXd>& t);

// Each record of a joined record cut in two: the first (1 - last_share) of its rows, and the
// rest. The first parts are joined again, and the last parts, so that every record (every
// maneuver of a joint fit) is in both; metadata: `data`'s. One record: rows [0, split) and
// [split, end). InputError "`what`: ..." when a record's part would hold fewer than min_rows.
struct RecordSplit {
  Dataset first, last;
};
RecordSplit SplitEachRecord(const Dataset& data, double last_share, long min_rows,
                            const std::string& what);

// Splits "a.csv,b.csv" at the commas; InputError "`what`: ..." for an empty list or name.
std::vector<std::string> RecordList(const std::string& text, const std::string& what);

}  // namespace usvid
