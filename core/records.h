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
// (how many) and "source" (each record's source, joined by ", "). One record comes back as it
// is. Throws InputError for an empty list.
Dataset JoinRecords(std::vector<Dataset> records, std::vector<std::string>* dropped = nullptr);

// The first row of each record in `t`, a joined record's times: row 0, then every row that
// follows a jump of at least half kRecordGapS (a log's own gaps, GPS dropouts of seconds, are
// not records). One record: {0}; no rows: {}.
std::vector<long> RecordStarts(const Eigen::Ref<const Eigen::VectorXd>& t);

// Splits "a.csv,b.csv" at the commas; InputError "`what`: ..." for an empty list or name.
std::vector<std::string> RecordList(const std::string& text, const std::string& what);

}  // namespace usvid
