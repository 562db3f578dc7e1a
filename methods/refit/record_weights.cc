#include "methods/refit/record_weights.h"

#include <algorithm>

namespace usvid {

std::vector<double> RecordWeights(
    const std::vector<std::pair<Eigen::Index, Eigen::Index>>& segments,
    const std::vector<long>& record_starts) {
  std::vector<size_t> record(segments.size(), 0);
  std::vector<long> count(std::max<size_t>(1, record_starts.size()), 0);
  for (size_t j = 0; j < segments.size(); ++j) {
    const auto after = std::upper_bound(record_starts.begin(), record_starts.end(),
                                        static_cast<long>(segments[j].first));
    record[j] =
        after == record_starts.begin() ? 0 : static_cast<size_t>(after - record_starts.begin() - 1);
    ++count[record[j]];
  }
  const long used = std::ranges::count_if(count, [](long c) { return c > 0; });
  std::vector<double> weight(segments.size(), 1.0);
  if (used > 1)
    for (size_t j = 0; j < segments.size(); ++j)
      weight[j] = static_cast<double>(segments.size()) /
                  (static_cast<double>(used) * static_cast<double>(count[record[j]]));
  return weight;
}

}  // namespace usvid
