// The data file (docs/data.md#data-files): a header of column names, then one row per sample,
// comma-separated, '.' decimal point; column t [s] strictly increasing; an empty cell is a
// sample not taken (multi-rate logs); nan/inf, text, short or long rows are bad input.
// Every error is an InputError reading "file:line:column: what was wrong".
#pragma once

#include <string>
#include <string_view>

#include "core/dataset.h"

namespace usvid {

Dataset ParseDatasetCsv(std::string_view text, const std::string& file);
Dataset ReadDatasetCsv(const std::string& path);

// t first, then the channels in order; unsampled values as empty cells; numbers in their
// shortest exact form, so reading the file back gives the same doubles.
std::string FormatDatasetCsv(const Dataset& data);
// Written atomically: a temporary file beside `path`, then a rename.
void WriteDatasetCsv(const std::string& path, const Dataset& data);

}  // namespace usvid
