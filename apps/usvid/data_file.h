// Reading a data CSV for a command (core/csv_dataset.h), as a user sees it on stderr: the share
// read of a long file, and one note per text column that is kept aside.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/dataset.h"

namespace usvid {

// `command` starts each stderr line, e.g. "usvid identify". Progress is printed for files of at
// least 16 MiB, about every tenth of the file.
Dataset ReadDataFile(const std::string& path, const std::string& command);

// "a.csv,b.csv,...": each file read as above, `each` applied to it (may be empty), checked for
// the `required` channels (InputError "FILE: no channel 'x' ..."), and the records joined for
// one fit (core/records.h), with a note on stderr of the channels left out and the joint length.
// One file is read as ReadDataFile reads it. InputError for an empty list or file name.
Dataset ReadDataFiles(const std::string& list, const std::string& command,
                      const std::vector<std::string>& required,
                      const std::function<void(Dataset&)>& each = {});

}  // namespace usvid
