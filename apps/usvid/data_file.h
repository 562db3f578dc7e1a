// Reading a data CSV for a command (core/csv_dataset.h), as a user sees it on stderr: the share
// read of a long file, and one note per text column that is kept aside.
#pragma once

#include <string>

#include "core/dataset.h"

namespace usvid {

// `command` starts each stderr line, e.g. "usvid identify". Progress is printed for files of at
// least 16 MiB, about every tenth of the file.
Dataset ReadDataFile(const std::string& path, const std::string& command);

}  // namespace usvid
