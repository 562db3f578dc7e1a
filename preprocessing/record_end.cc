#include "preprocessing/record_end.h"

#include <cmath>
#include <sstream>
#include <vector>

#include "core/error.h"

namespace usvid {

RecordEnd FindRecordEnd(const Dataset& data, const std::string& channel) {
  const Channel* c = data.Find(channel);
  if (c == nullptr)
    throw InputError(data.SourcePrefix() + "no column '" + channel + "' to end the record at");
  if (!c->FullySampled())
    throw InputError(data.SourcePrefix() + "'" + channel +
                     "' has empty cells: the record's end cannot be told");
  const Eigen::VectorXd& x = c->values();
  const double largest = x.cwiseAbs().maxCoeff();
  Eigen::Index last = -1;
  for (Eigen::Index k = x.size() - 1; k >= 0 && largest > 0.0; --k) {
    if (std::abs(x(k)) > 0.01 * largest) {
      last = k;
      break;
    }
  }
  if (last < 0)
    throw InputError(data.SourcePrefix() + "'" + channel + "' never runs: no test to end");
  const Eigen::VectorXd& t = data.t();
  RecordEnd end;
  end.t_end = t(last);
  end.dropped_s = t(t.size() - 1) - t(last);
  end.dropped_rows = static_cast<int>(x.size() - 1 - last);
  return end;
}

RecordEnd EndAtStop(Dataset& data, const std::string& channel) {
  const RecordEnd end = FindRecordEnd(data, channel);
  std::vector<bool> keep(data.rows(), true);
  for (Eigen::Index k = data.rows() - end.dropped_rows; k < data.rows(); ++k) keep[k] = false;
  data.KeepRows(keep);
  return end;
}

std::string DescribeRecordEnd(const RecordEnd& end, const std::string& channel) {
  std::ostringstream s;
  s << std::fixed;
  s.precision(1);
  s << "ended where " << channel << " stopped, at t = " << end.t_end << " s: " << end.dropped_s
    << " s (" << end.dropped_rows << " rows) dropped";
  return s.str();
}

}  // namespace usvid
