#include "core/error.h"

#include <sstream>

namespace usvid {

std::string Located(const std::string& file, int line, int column, const std::string& what) {
  std::ostringstream out;
  out << file;
  if (line > 0) out << ':' << line;
  if (line > 0 && column > 0) out << ':' << column;
  out << ": " << what;
  return out.str();
}

}  // namespace usvid
