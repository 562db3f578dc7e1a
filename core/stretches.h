// Where a time series is continuous. A gap is an interval between consecutive rows longer than
// `factor` times the median interval: a dropout inside a record, or the join between two records
// (core/records.h). No derivative, segment or simulation may run across one
// (docs/data.md#several-records-and-gaps).
#pragma once

#include <Eigen/Core>
#include <vector>

namespace usvid {

// On a uniform grid (preprocessed data) a dropped row leaves an interval of two steps or more.
inline constexpr double kGridGapFactor = 1.5;
// In a raw log, whose sampling jitters, as resampling counts a gap (preprocessing/resample.h).
inline constexpr double kRawGapFactor = 4.0;

// Rows [first, end) without a gap between them.
struct Stretch {
  Eigen::Index first = 0, end = 0;
  Eigen::Index rows() const { return end - first; }
};

// The longest interval that is not a gap: factor x the median interval (infinite for fewer than
// two rows).
double GapLimit(const Eigen::Ref<const Eigen::VectorXd>& t, double factor);

// The stretches between gaps, in order; one for a series without gaps, none for no rows.
std::vector<Stretch> Stretches(const Eigen::Ref<const Eigen::VectorXd>& t, double factor);

}  // namespace usvid
