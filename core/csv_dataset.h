// The data file (docs/data.md#data-files): a header of column names, then one row per sample,
// comma-separated, '.' decimal point; column t [s] strictly increasing; an empty cell is a
// sample not taken (multi-rate logs); nan/inf, short or long rows are bad input, and so is text
// in a column that has held a number. A column whose first value is text (a mode, a comment) is
// a text column: not stored, and refused with its first text's file:line:column only by a
// command that needs it as a number (Dataset::Get).
// Every error is an InputError reading "file:line:column: what was wrong".
#pragma once

#include <functional>
#include <string>
#include <string_view>

#include "core/dataset.h"

namespace usvid {

struct CsvReadOptions {
  // Called about every tenth of the file with the share read and the rows so far.
  std::function<void(double fraction, Eigen::Index rows)> progress;
};

Dataset ParseDatasetCsv(std::string_view text, const std::string& file);
// Streams the file a line at a time into columns sized once (a first pass counts the lines):
// the data take their doubles and a byte per cell for the mask, and the text is never whole in
// memory. When the record file RecordJsonPath(path) exists, its "maneuver" goes into metadata
// "maneuver"; a record file that is not a JSON object with a non-empty string "maneuver" is an
// InputError naming it.
Dataset ReadDatasetCsv(const std::string& path, const CsvReadOptions& options = {});

// The record file beside a data file, F.csv -> F.record.json (F -> F.record.json): what `usvid
// import` knew of the record that its columns do not hold, such as the maneuver named in a log's
// header (docs/data.md#the-records-maneuver-frecordjson).
std::string RecordJsonPath(const std::string& data_path);

// t first, then the channels in order; unsampled values as empty cells; numbers in their
// shortest exact form, so reading the file back gives the same doubles.
std::string FormatDatasetCsv(const Dataset& data);
// Written atomically: a temporary file beside `path`, then a rename.
void WriteDatasetCsv(const std::string& path, const Dataset& data);

}  // namespace usvid
