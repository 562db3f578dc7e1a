// libFuzzer target: the equation parser of model.json (core/expression.h). Any text either
// parses (and then evaluates without crashing on any variable values) or is refused with
// InputError naming the column.
#include <cstdint>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/expression.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const usvid::Expression e = usvid::Expression::Parse(text, "fuzz");
    std::vector<double> values(e.Variables().size(), 0.5);
    (void)e.Evaluate(values);
    for (double& v : values) v = -1e300;
    (void)e.Evaluate(values);
  } catch (const usvid::InputError&) {
  }
  return 0;
}
