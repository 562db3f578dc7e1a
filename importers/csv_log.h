// Any CSV log into a data file (docs/data.md#data-files). The separator (',', ';' or tab) is
// detected from the header. With a column map only the mapped columns are read (others may hold
// text, such as dates); without one every column is read and must be numeric. Time comes from
// the channel t (map it: --map t=time). Rows whose time does not increase are dropped and
// reported; vn/ve become body-fixed u/v (column_map.h).
#pragma once

#include <string>
#include <vector>

#include "core/dataset.h"
#include "importers/column_map.h"
#include "importers/import_report.h"

namespace usvid {

Dataset ImportCsvLog(const std::string& path, const std::vector<ColumnMapping>& map,
                     ImportReport& report);
Dataset ParseCsvLog(const std::string& text, const std::string& file,
                    const std::vector<ColumnMapping>& map, ImportReport& report);

// The columns of a CSV log's header line, named as ImportCsvLog names them (the separator
// detected alike); only the header is read. Throws InputError for a file without one.
std::vector<std::string> CsvLogColumns(const std::string& path);

}  // namespace usvid
