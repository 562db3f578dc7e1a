// Train / held-out splits of time series that never leak: whole files (maneuvers), contiguous
// blocks of one series, or k folds over blocks. Random samples of one series are never used for
// held-out scores: neighbouring samples are nearly equal, so such "held-out" data are seen data.
#pragma once

#include <utility>
#include <vector>

#include "core/dataset.h"

namespace usvid {

// Row ranges [begin, end).
using RowRange = std::pair<Eigen::Index, Eigen::Index>;

// `count` contiguous blocks of as equal length as possible.
std::vector<RowRange> ContiguousBlocks(Eigen::Index rows, int count);

struct Fold {
  std::vector<RowRange> train;
  std::vector<RowRange> held_out;
};

// k folds: fold i holds out block i and trains on the others. Throws InputError for k < 2.
std::vector<Fold> BlockFolds(Eigen::Index rows, int k);

// k folds over several pieces (records, or stretches between gaps): each piece is cut into k
// contiguous blocks and fold i holds out block i of every piece, so every fold holds out a
// share of every maneuver rather than whole maneuvers the others never saw. A piece of fewer
// than k rows is never held out (it trains every fold). One piece: BlockFolds(rows, k).
// Throws InputError for k < 2.
std::vector<Fold> BlockFolds(const std::vector<RowRange>& pieces, int k);

// The rows of a range as a dataset of its own (time kept as it is).
Dataset Rows(const Dataset& data, RowRange range);

// Train on the first `fraction` of the rows, hold out the rest (the usual single split).
std::pair<Dataset, Dataset> SplitAt(const Dataset& data, double fraction);

}  // namespace usvid
