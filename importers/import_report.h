// What an importer did to a log, one line per action, printed by `usvid import` on stderr:
// a repair is reported, never silent.
#pragma once

#include <string>
#include <vector>

namespace usvid {

struct ImportReport {
  std::vector<std::string> notes;
  void Note(std::string line) { notes.push_back(std::move(line)); }
};

}  // namespace usvid
