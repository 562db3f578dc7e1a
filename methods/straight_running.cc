#include "methods/straight_running.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/median.h"

namespace usvid {

bool MirrorTurnsOver(std::string_view channel) {
  static constexpr std::array<std::string_view, 10> kTurnedOver = {
      "v", "r", "delta", "nozzle", "tau_y", "tau_n", "wind_v", "current_v", "p", "phi"};
  return std::ranges::find(kTurnedOver, channel) != kTurnedOver.end();
}

ChannelLevel LevelOf(std::vector<double> samples) {
  ChannelLevel level;
  if (samples.empty()) return level;
  double sum = 0.0;
  for (double x : samples) sum += x * x;
  level.rms = std::sqrt(sum / static_cast<double>(samples.size()));
  level.median = SampleMedian(std::move(samples));
  return level;
}

std::vector<std::vector<double>> StraightRunningPoints(const std::vector<std::string>& names,
                                                       const std::vector<ChannelLevel>& levels,
                                                       size_t state) {
  std::vector<double> point(names.size());
  for (size_t i = 0; i < names.size(); ++i)
    point[i] = MirrorTurnsOver(names[i]) ? 0.0 : levels[i].median;
  if (!MirrorTurnsOver(names[state])) return {point};
  std::vector<std::vector<double>> both(2, point);
  both[0][state] = levels[state].rms;
  both[1][state] = -levels[state].rms;
  return both;
}

}  // namespace usvid
