// libFuzzer target: the comparison suite reader (harness/suite.h) from JSON text, as
// `usvid compare --suite` reads a file. Any input is a suite, or InputError naming the file;
// nothing else escapes.
#include <cstdint>
#include <string>

#include "core/error.h"
#include "core/json_file.h"
#include "harness/suite.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const usvid::Suite s = usvid::ParseSuite(usvid::ParseJson(text, "fuzz.json"), "fuzz.json");
    (void)usvid::SuiteToJson(s);
    (void)usvid::FitJobs(s);
  } catch (const usvid::InputError&) {
  }
  return 0;
}
