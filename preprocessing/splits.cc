#include "preprocessing/splits.h"

#include <cmath>

#include "core/error.h"

namespace usvid {

std::vector<RowRange> ContiguousBlocks(Eigen::Index rows, int count) {
  if (count < 1 || rows < count)
    throw InputError("split: cannot cut " + std::to_string(rows) + " rows into " +
                     std::to_string(count) + " blocks");
  std::vector<RowRange> blocks;
  for (int b = 0; b < count; ++b) blocks.push_back({rows * b / count, rows * (b + 1) / count});
  return blocks;
}

std::vector<Fold> BlockFolds(Eigen::Index rows, int k) { return BlockFolds({{0, rows}}, k); }

std::vector<Fold> BlockFolds(const std::vector<RowRange>& pieces, int k) {
  if (k < 2) throw InputError("split: k-fold needs k >= 2");
  std::vector<Fold> folds(static_cast<size_t>(k));
  for (const auto& [first, end] : pieces) {
    if (end - first < k) {
      for (Fold& f : folds) f.train.push_back({first, end});
      continue;
    }
    const std::vector<RowRange> blocks = ContiguousBlocks(end - first, k);
    for (int i = 0; i < k; ++i)
      for (int j = 0; j < k; ++j) {
        const RowRange block{first + blocks[j].first, first + blocks[j].second};
        (j == i ? folds[i].held_out : folds[i].train).push_back(block);
      }
  }
  return folds;
}

Dataset Rows(const Dataset& data, RowRange range) {
  std::vector<bool> keep(data.rows(), false);
  for (Eigen::Index i = range.first; i < range.second; ++i) keep[i] = true;
  Dataset out = data;
  out.KeepRows(keep);
  return out;
}

std::pair<Dataset, Dataset> SplitAt(const Dataset& data, double fraction) {
  if (!(fraction > 0 && fraction < 1)) throw InputError("split: the fraction must be in (0, 1)");
  const auto cut = static_cast<Eigen::Index>(std::llround(fraction * data.rows()));
  return {Rows(data, {0, cut}), Rows(data, {cut, data.rows()})};
}

}  // namespace usvid
