#include "harness/bootstrap.h"

#include <cmath>
#include <random>
#include <string>

#include "core/error.h"
#include "metrics/rank_tests.h"

namespace usvid {

BootstrapInterval BootstrapMean(const std::vector<double>& values, int resamples, double level,
                                uint64_t seed) {
  if (resamples < 1)
    throw InputError("bootstrap: resamples " + std::to_string(resamples) + ": at least 1");
  if (!(level > 0.0 && level < 1.0))
    throw InputError("bootstrap: level " + std::to_string(level) + ": in (0, 1)");
  BootstrapInterval out;
  out.n = static_cast<int>(values.size());
  double sum = 0.0;
  for (size_t i = 0; i < values.size(); ++i) {
    if (!std::isfinite(values[i]))
      throw InputError("bootstrap: value " + std::to_string(i) + " is " +
                       std::to_string(values[i]) + ": finite values only");
    sum += values[i];
  }
  if (values.empty()) {
    out.mean = out.low = out.high = NAN;
    return out;
  }
  out.mean = sum / static_cast<double>(values.size());
  std::mt19937_64 draw(seed);
  const uint64_t n = values.size();
  std::vector<double> means(static_cast<size_t>(resamples));
  for (double& m : means) {
    double s = 0.0;
    for (uint64_t i = 0; i < n; ++i) s += values[draw() % n];
    m = s / static_cast<double>(n);
  }
  const double tail = (1.0 - level) / 2.0;
  out.low = Quantile(means, tail);
  out.high = Quantile(std::move(means), 1.0 - tail);
  return out;
}

}  // namespace usvid
