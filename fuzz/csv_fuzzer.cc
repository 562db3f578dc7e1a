// libFuzzer target: the strict data CSV reader (docs/data.md#data-files). Any input either parses
// into a dataset whose time is strictly increasing and whose sampled cells are finite, or is
// refused with InputError; nothing else (no crash, no other exception, no sanitizer report).
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "core/check.h"
#include "core/csv_dataset.h"
#include "core/error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const usvid::Dataset d = usvid::ParseDatasetCsv(text, "fuzz.csv");
    for (Eigen::Index k = 1; k < d.rows(); ++k)
      USVID_CHECK(d.t()(k) > d.t()(k - 1), "accepted time stamps must increase");
    for (const usvid::Channel& c : d.channels())
      for (Eigen::Index k = 0; k < d.rows(); ++k)
        USVID_CHECK(!c.IsSampled(k) || std::isfinite(c.Value(k)), "accepted samples are finite");
    // What was read writes back and reads again to the same values.
    const usvid::Dataset again = usvid::ParseDatasetCsv(usvid::FormatDatasetCsv(d), "again.csv");
    USVID_CHECK(again.rows() == d.rows(), "a written file reads back with its rows");
  } catch (const usvid::InputError&) {
  }
  return 0;
}
