#include "methods/gp/model_selection.h"

#include <algorithm>
#include <cmath>
#include <span>

#include "core/error.h"
#include "methods/gp/segment_simulator.h"

namespace usvid::gp {
Selection SelectModels(const SelectionData& data, const std::vector<StateCandidates>& states) {
  const long rows = data.t.size();
  std::vector<int> state_vars;
  for (const StateCandidates& s : states) {
    const auto it = std::find(data.names.begin(), data.names.end(), s.state);
    if (it == data.names.end())
      throw InputError("gp model selection: state '" + s.state + "' is not a variable");
    if (s.models.empty()) throw InputError("gp model selection: no candidates for " + s.state);
    state_vars.push_back(static_cast<int>(it - data.names.begin()));
  }
  if (data.validation_begin < 0 || rows - data.validation_begin < 2)
    throw InputError("gp model selection: the validation part has fewer than 2 samples");

  // Segments of the horizon over the validation rows (one shorter segment when it is short).
  const double dt = (data.t(rows - 1) - data.t(0)) / static_cast<double>(rows - 1);
  const long span = rows - 1 - data.validation_begin;
  const long steps = std::clamp<long>(std::lround(data.horizon_s / dt), 1, span);
  const std::vector<long> starts = SegmentSimulator::Starts(data.validation_begin, rows, steps);

  Selection out;
  out.candidate_scores.resize(states.size());
  // Each state's candidates on their own: that state integrated, the others as measured, so a
  // wrong equation of one state cannot make a wrong one of another look right.
  std::vector<std::vector<size_t>> ranked(states.size());
  for (size_t s = 0; s < states.size(); ++s) {
    const std::vector<Model>& models = states[s].models;
    const SegmentSimulator sim(data, {state_vars[s]});
    std::vector<std::vector<double>> segments(models.size());
    for (size_t c = 0; c < models.size(); ++c) {
      bool diverged = false;
      const double e = sim.Error({&models[c]}, starts, steps, diverged, &segments[c]);
      out.candidate_scores[s].push_back({c, std::isfinite(e) ? e : INFINITY});
      ++out.candidates_scored;
    }
    // The one-standard-error rule: the smallest candidate within one standard error (over
    // segments) of the smallest error comes first, then the rest by error.
    size_t best = 0;
    for (size_t c = 1; c < models.size(); ++c)
      if (out.candidate_scores[s][c].score < out.candidate_scores[s][best].score) best = c;
    double se = 0.0;
    const std::vector<double>& e = segments[best];
    if (e.size() > 1 && std::isfinite(out.candidate_scores[s][best].score)) {
      const double mean = out.candidate_scores[s][best].score;
      for (double x : e) se += (x - mean) * (x - mean);
      se = std::sqrt(se / static_cast<double>(e.size() - 1) / static_cast<double>(e.size()));
    }
    size_t pick = best;
    for (size_t c = 0; c < models.size(); ++c)
      if (out.candidate_scores[s][c].score <= out.candidate_scores[s][best].score + se &&
          (models[c].Size() < models[pick].Size() ||
           (models[c].Size() == models[pick].Size() &&
            out.candidate_scores[s][c].score < out.candidate_scores[s][pick].score)))
        pick = c;
    std::vector<ScoredCandidate> order = out.candidate_scores[s];
    std::stable_sort(
        order.begin(), order.end(), [&](const ScoredCandidate& a, const ScoredCandidate& b) {
          if ((a.index == pick) != (b.index == pick)) return a.index == pick;
          return a.score < b.score ||
                 (a.score == b.score && models[a.index].Size() < models[b.index].Size());
        });
    for (const ScoredCandidate& c : order) ranked[s].push_back(c.index);
    out.standard_errors.push_back(se);
  }

  // The best of each, then one state at a time moved to its next best, until the whole model
  // free-runs the training record within the bounds.
  const SegmentSimulator joint(data, state_vars);
  std::vector<std::vector<size_t>> tries = {std::vector<size_t>(states.size(), 0)};
  for (size_t k = 1; tries.size() < 20; ++k) {
    bool any = false;
    for (size_t s = 0; s < states.size() && tries.size() < 20; ++s)
      if (k < ranked[s].size()) {
        std::vector<size_t> rank(states.size(), 0);
        rank[s] = k;
        tries.push_back(rank);
        any = true;
      }
    if (!any) break;
  }
  auto combination = [&](const std::vector<size_t>& rank) {
    std::vector<size_t> combo;
    for (size_t s = 0; s < states.size(); ++s) combo.push_back(ranked[s][rank[s]]);
    return combo;
  };
  out.chosen = combination(tries[0]);
  out.free_run_diverged = true;
  for (const std::vector<size_t>& rank : tries) {
    const std::vector<size_t> combo = combination(rank);
    std::vector<const Model*> models;
    for (size_t s = 0; s < states.size(); ++s) models.push_back(&states[s].models[combo[s]]);
    bool diverged = false;
    joint.Error(models, {0}, rows - 1, diverged);
    if (!diverged) {
      out.chosen = combo;
      out.free_run_diverged = false;
      break;
    }
    ++out.rejected_for_divergence;
  }
  for (size_t s = 0; s < states.size(); ++s)
    out.scores.push_back(out.candidate_scores[s][out.chosen[s]].score);
  return out;
}

}  // namespace usvid::gp
