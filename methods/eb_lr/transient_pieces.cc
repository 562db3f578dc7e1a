#include "methods/eb_lr/transient_pieces.h"

#include <algorithm>

namespace usvid::eb_lr {

std::vector<SteadyWindow> TransientRuns(Eigen::Index n, const std::vector<SteadyWindow>& windows,
                                        Eigen::Index margin) {
  std::vector<int> window_of(n, -1);
  for (size_t w = 0; w < windows.size(); ++w)
    for (Eigen::Index k = windows[w].first; k <= windows[w].last; ++k)
      window_of[k] = static_cast<int>(w);
  std::vector<SteadyWindow> runs;
  for (Eigen::Index k = 0; k < n; ++k) {
    if (window_of[k] >= 0) continue;
    SteadyWindow run{k, k};
    while (run.last + 1 < n && window_of[run.last + 1] < 0) ++run.last;
    k = run.last;
    if (run.first > 0) {
      const SteadyWindow& w = windows[window_of[run.first - 1]];
      run.first = std::max(w.last - margin, (w.first + w.last) / 2);
    }
    if (run.last + 1 < n) {
      const SteadyWindow& w = windows[window_of[run.last + 1]];
      run.last = std::min(w.first + margin, (w.first + w.last) / 2);
    }
    if (run.last > run.first) runs.push_back(run);
  }
  return runs;
}

std::vector<SteadyWindow> TransientPieces(const std::vector<SteadyWindow>& runs,
                                          Eigen::Index piece) {
  std::vector<SteadyWindow> pieces;
  for (const SteadyWindow& run : runs)
    for (Eigen::Index a = run.first; a < run.last;) {
      Eigen::Index b = std::min(run.last, a + piece);
      if (run.last - b < piece / 2) b = run.last;
      pieces.push_back({a, b});
      a = b;
    }
  return pieces;
}

}  // namespace usvid::eb_lr
