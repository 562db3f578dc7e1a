#include "metrics/recorded_tests.h"

#include "core/error.h"
#include "core/records.h"

namespace usvid {

std::vector<RecordedTest> RecordedTests(const Dataset& train, const VesselRef& vessel,
                                        const std::vector<std::string>& kinds) {
  std::vector<RecordedTest> out;
  const std::vector<long> starts = RecordStarts(train.t());
  for (size_t i = 0; i < starts.size(); ++i) {
    const long end = i + 1 < starts.size() ? starts[i + 1] : static_cast<long>(train.rows());
    Dataset record = train.Rows(starts[i], end - starts[i]);
    record.SetTime(record.t().array() - record.t()(0));
    for (const std::string& kind : kinds) {
      try {
        const std::string spec = RecordedManeuverSpec(kind, vessel, record);
        if (!spec.starts_with(kind + ":")) continue;
        out.push_back({spec, ManeuverScorer(vessel, spec, record)});
        break;
      } catch (const InputError&) {
        // not this test (no heading or rudder, or a record that holds another one)
      }
    }
  }
  return out;
}

}  // namespace usvid
