#include "metrics/recorded_yaw_rate.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace usvid {

namespace {

// A hold longer than this ends a move: the next change is a new order.
constexpr double kMoveGapS = 1.0;

struct Move {
  double change = 0.0;  // absolute
  double seconds = 0.0;
};

// The record's moves of one channel, in time order.
std::vector<Move> MovesOf(const Eigen::VectorXd& t, const Eigen::VectorXd& x) {
  std::vector<Move> moves;
  int sign = 0;
  Eigen::Index first = 0, last = 0;  // rows before the move's first change and at its last
  auto close = [&] {
    if (sign != 0)
      moves.push_back({std::abs(x(last) - x(first)), std::max(t(last) - t(first), 0.0)});
    sign = 0;
  };
  for (Eigen::Index k = 1; k < x.size(); ++k) {
    const double d = x(k) - x(k - 1);
    if (!std::isfinite(d)) {
      close();
      continue;
    }
    if (d == 0.0) {
      if (sign != 0 && t(k) - t(last) > kMoveGapS) close();
      continue;
    }
    const int s = d > 0 ? 1 : -1;
    if (s != sign) {
      close();
      sign = s;
      first = k - 1;
    }
    last = k;
  }
  close();
  return moves;
}

}  // namespace

double LargeMoveRate(const Dataset& recorded, const std::string& channel, double min_move) {
  if (!recorded.Has(channel) || recorded.rows() < 2) return 0.0;
  const std::vector<Move> moves = MovesOf(recorded.t(), recorded[channel]);
  double largest = 0.0;
  for (const Move& m : moves) largest = std::max(largest, m.change);
  std::vector<double> rates;
  for (const Move& m : moves)
    if (m.change >= 0.5 * largest && m.change >= min_move && m.seconds > 0.0)
      rates.push_back(m.change / m.seconds);
  if (rates.empty()) return 0.0;
  const auto mid = rates.begin() + static_cast<std::ptrdiff_t>(rates.size() / 2);
  std::nth_element(rates.begin(), mid, rates.end());
  return *mid;
}

double ReplayYawRateLimit(const Actuation& act, const Dataset& recorded) {
  if (!(act.yaw_rate_limit > 0) || act.yaw_input < 0) return act.yaw_rate_limit;
  const double min_move = std::abs(act.YawCommand(2.0) - act.YawCommand(0.0));
  const double rate = LargeMoveRate(recorded, act.input_names[act.yaw_input], min_move);
  return rate > 2.0 * act.yaw_rate_limit ? 0.0 : act.yaw_rate_limit;
}

}  // namespace usvid
