// usvid info --data F.csv: checks a data file against the contract (section 1) and summarises
// it: rows, duration, and per channel the samples taken, the sampling rate and the range.

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <memory>
#include <vector>

#include "apps/usvid/commands.h"
#include "core/csv_dataset.h"

namespace usvid {
namespace {

// Median interval between the samples a channel took, in seconds (0 with fewer than two).
double MedianInterval(const Eigen::VectorXd& t, const Channel& c) {
  std::vector<double> gaps;
  double last = -1.0;
  bool have_last = false;
  for (Eigen::Index i = 0; i < t.size(); ++i) {
    if (!c.sampled(i)) continue;
    if (have_last) gaps.push_back(t(i) - last);
    last = t(i);
    have_last = true;
  }
  if (gaps.empty()) return 0.0;
  std::nth_element(gaps.begin(), gaps.begin() + gaps.size() / 2, gaps.end());
  return gaps[gaps.size() / 2];
}

void RunInfo(const std::string& path) {
  const Dataset d = ReadDatasetCsv(path);
  std::printf("%s: %ld rows, t from %g to %g s (%g s)\n", path.c_str(), static_cast<long>(d.rows()),
              d.t()(0), d.t()(d.rows() - 1), d.duration());
  std::printf("%-16s %9s %10s %14s %14s\n", "channel", "samples", "rate [Hz]", "min", "max");
  for (const Channel& c : d.channels()) {
    const long n = c.sampled.count();
    const double gap = MedianInterval(d.t(), c);
    double lo = 0.0, hi = 0.0;
    if (n > 0) {
      lo = c.sampled.select(c.values.array(), INFINITY).minCoeff();
      hi = c.sampled.select(c.values.array(), -INFINITY).maxCoeff();
    }
    std::printf("%-16s %9ld %10.4g %14.6g %14.6g\n", c.name.c_str(), n, gap > 0 ? 1.0 / gap : 0.0,
                lo, hi);
  }
}

}  // namespace

void AddInfoCommand(CLI::App& app) {
  auto path = std::make_shared<std::string>();
  CLI::App* cmd = app.add_subcommand(
      "info", "Check a data CSV against the contract and summarise its channels and rates");
  cmd->add_option("--data", *path, "The data CSV to check")->required();
  cmd->callback([path] { RunInfo(*path); });
}

}  // namespace usvid
