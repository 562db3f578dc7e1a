#include "methods/gp/validation_split.h"

#include <cmath>

#include "core/records.h"
#include "core/stretches.h"

namespace usvid::gp {

ValidationSplit SplitForValidation(const PreparedData& prepared, double f) {
  const std::vector<Stretch> stretches = Stretches(prepared.data.t(), kGridGapFactor);
  ValidationSplit out;
  if (f <= 0 || stretches.size() < 2) return out;
  std::vector<Dataset> pieces, check;
  for (const Stretch& s : stretches) {
    const long v = std::lround(f * static_cast<double>(s.rows()));
    const bool whole = v < 2 || s.rows() - v < 2;
    pieces.push_back(prepared.data.Rows(s.first, whole ? s.rows() : s.rows() - v));
    out.train_rows += pieces.back().rows();
    if (!whole) check.push_back(prepared.data.Rows(s.end - v, v));
  }
  for (Dataset& d : check) pieces.push_back(std::move(d));
  out.reordered = prepared;
  out.reordered->data = JoinRecords(std::move(pieces));
  out.reordered->data.metadata() = prepared.data.metadata();
  return out;
}

}  // namespace usvid::gp
