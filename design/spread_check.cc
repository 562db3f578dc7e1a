#include "design/spread_check.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/model_view.h"
#include "methods/identify.h"

namespace usvid::design {

SpreadCheck CheckSpread(const DesignProblem& problem, const ManeuverInformation& predicted,
                        int runs, int threads) {
  if (runs < 2)
    throw InputError("design: --check needs at least 2 runs, not " + std::to_string(runs));
  const size_t n = predicted.names.size();
  std::vector<std::vector<double>> estimates(static_cast<size_t>(runs));
#pragma omp parallel for schedule(dynamic) num_threads(std::max(1, threads))
  for (int k = 0; k < runs; ++k) {
    try {
      // The maneuver as designed, with noise drawn from the run's own seed.
      const Dataset data = NoisyRun(problem, predicted.maneuver, static_cast<uint64_t>(k + 1));
      IdentifyRequest r;
      r.method = problem.method;
      r.vessel = problem.vessel;
      r.threads = 1;
      const nlohmann::json model = Identify(data, r);
      std::vector<double> p;
      for (const std::string& name : predicted.names) {
        const std::optional<double> value = ModelView(model).Parameter(name);
        if (!value) throw InputError("the fit has no parameter " + name);  // counted, not scored
        p.push_back(*value);
      }
      estimates[static_cast<size_t>(k)] = std::move(p);
    } catch (const std::exception&) {
      // A failed fit is counted, not scored.
    }
  }
  SpreadCheck c;
  c.runs = runs;
  std::vector<std::vector<double>> ok;
  for (auto& e : estimates)
    if (e.size() == n && std::all_of(e.begin(), e.end(), [](double v) { return std::isfinite(v); }))
      ok.push_back(e);
  c.failed = runs - static_cast<int>(ok.size());
  if (ok.size() < 2) return c;
  for (size_t i = 0; i < n; ++i) {
    double mean = 0.0, ss = 0.0;
    for (const auto& e : ok) mean += e[i];
    mean /= static_cast<double>(ok.size());
    for (const auto& e : ok) ss += (e[i] - mean) * (e[i] - mean);
    const double sd = std::sqrt(ss / static_cast<double>(ok.size() - 1));
    c.mean.push_back(mean);
    c.observed_sd.push_back(sd);
    c.ratio.push_back(sd > 0.0 ? predicted.sd[i] / sd : 0.0);
  }
  std::vector<double> r = c.ratio;
  std::nth_element(r.begin(), r.begin() + static_cast<long>(r.size() / 2), r.end());
  c.median_ratio = r[r.size() / 2];
  if (r.size() % 2 == 0) {
    const double lower = *std::max_element(r.begin(), r.begin() + static_cast<long>(r.size() / 2));
    c.median_ratio = 0.5 * (c.median_ratio + lower);
  }
  return c;
}

}  // namespace usvid::design
