#include "preprocessing/resample.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "core/error.h"
#include "core/median.h"
#include "preprocessing/cubic_spline.h"

namespace usvid {

std::vector<std::string> ResampleReport::Summary() const {
  std::vector<std::string> lines;
  for (const ChannelResampling& c : channels) {
    std::ostringstream s;
    s << c.channel << ": " << c.samples_in << " samples every " << c.median_interval_s << " s";
    if (c.gaps > 0) s << ", " << c.gaps << " gap(s) not bridged";
    if (c.unsampled > 0) s << ", " << c.unsampled << " grid points left empty";
    lines.push_back(s.str());
  }
  return lines;
}

Dataset Resample(const Dataset& data, const ResampleOptions& options, ResampleReport* report) {
  if (!(options.rate_hz > 0)) throw InputError("resample: the rate must be positive");
  if (data.rows() < 2) throw InputError("resample: the data need at least two rows");
  const double t0 = data.t()(0), t1 = data.t()(data.rows() - 1);
  const double step = 1.0 / options.rate_hz;
  const auto n = static_cast<Eigen::Index>(std::floor((t1 - t0) / step + 1e-6)) + 1;
  Dataset out(Eigen::VectorXd::LinSpaced(n, t0, t0 + (n - 1) * step));
  out.metadata() = data.metadata();

  for (const Channel& c : data.channels()) {
    if (!options.channels.empty() &&
        std::find(options.channels.begin(), options.channels.end(), c.name) ==
            options.channels.end())
      continue;
    std::vector<double> ts, ys;
    c.ForEachSample([&](Eigen::Index i, double v) {
      ts.push_back(data.t()(i));
      ys.push_back(v);
    });
    if (ts.size() < 2)
      throw InputError("resample: channel '" + c.name + "' has fewer than two samples");
    std::vector<double> gaps_between(ts.size() - 1);
    for (size_t k = 0; k + 1 < ts.size(); ++k) gaps_between[k] = ts[k + 1] - ts[k];
    ChannelResampling info{c.name, static_cast<long>(ts.size()), SampleMedian(gaps_between), 0, 0};
    const double max_gap = options.max_gap_s > 0 ? options.max_gap_s : 4 * info.median_interval_s;

    // Split into stretches without a long gap; each is interpolated on its own.
    std::vector<std::pair<size_t, size_t>> stretches;  // [first, last] sample indices
    size_t first = 0;
    for (size_t k = 0; k + 1 < ts.size(); ++k) {
      if (gaps_between[k] > max_gap) {
        stretches.push_back({first, k});
        first = k + 1;
        ++info.gaps;
      }
    }
    stretches.push_back({first, ts.size() - 1});

    Eigen::VectorXd v = Eigen::VectorXd::Zero(n);
    Eigen::Array<bool, Eigen::Dynamic, 1> s = Eigen::Array<bool, Eigen::Dynamic, 1>::Zero(n);
    for (const auto& [a, b] : stretches) {
      const std::vector<double> st(ts.begin() + a, ts.begin() + b + 1);
      const std::vector<double> sy(ys.begin() + a, ys.begin() + b + 1);
      const bool spline = options.interpolation == Interpolation::kCubicSpline && st.size() >= 3;
      std::optional<CubicSpline> cs;
      if (spline) cs.emplace(st, sy);
      const auto lo = static_cast<Eigen::Index>(std::ceil((st.front() - t0) / step - 1e-6));
      const auto hi = static_cast<Eigen::Index>(std::floor((st.back() - t0) / step + 1e-6));
      size_t k = 0;
      for (Eigen::Index i = std::max<Eigen::Index>(lo, 0); i <= std::min(hi, n - 1); ++i) {
        const double t = out.t()(i);
        if (st.size() == 1) {
          v(i) = sy[0];
        } else if (cs) {
          v(i) = (*cs)(t);
        } else {
          while (k + 2 < st.size() && st[k + 1] < t) ++k;
          const double w = std::clamp((t - st[k]) / (st[k + 1] - st[k]), 0.0, 1.0);
          v(i) = (1 - w) * sy[k] + w * sy[k + 1];
        }
        s(i) = true;
      }
    }
    info.unsampled = static_cast<long>(n - s.count());
    out.Set(c.name, std::move(v), std::move(s));
    if (report != nullptr) report->channels.push_back(info);
  }
  return out;
}

}  // namespace usvid
