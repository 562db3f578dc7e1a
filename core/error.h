// Errors by layer: bad user input throws InputError (caught once in main, exit code 2);
// internal invariants abort. The message names the file, line, column or option at fault.
#pragma once

#include <stdexcept>
#include <string>

namespace usvid {

class InputError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// A comparison found results worse than its baseline (usvid compare --baseline): exit code 3.
class RegressionFound : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// "file:line:column: what" (line and column are 1-based; 0 leaves them out).
std::string Located(const std::string& file, int line, int column, const std::string& what);

}  // namespace usvid
