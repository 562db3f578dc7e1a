#include "methods/gp/model_selection.h"

#include <algorithm>
#include <cmath>
#include <span>

#include "core/dataset.h"
#include "core/error.h"
#include "methods/gp/segment_simulator.h"

namespace usvid::gp {
namespace {

// Each state's index among the variables. Throws InputError for a state that is not a variable
// or has no candidates.
std::vector<int> StateVariables(const SelectionData& data,
                                const std::vector<StateCandidates>& states) {
  std::vector<int> state_vars;
  for (const StateCandidates& s : states) {
    const auto it = std::find(data.names.begin(), data.names.end(), s.state);
    if (it == data.names.end())
      throw InputError("gp model selection: state '" + s.state + "' is not a variable");
    if (s.models.empty()) throw InputError("gp model selection: no candidates for " + s.state);
    state_vars.push_back(static_cast<int>(it - data.names.begin()));
  }
  return state_vars;
}

// Each candidate's short-horizon error over the segments (infinite when not finite): the state
// `state_var` integrated, the others as measured. segments[c] receives candidate c's error per
// segment.
std::vector<ScoredCandidate> ScoreCandidates(const SelectionData& data, int state_var,
                                             const std::vector<Model>& models,
                                             const std::vector<long>& starts, long steps,
                                             std::vector<std::vector<double>>& segments) {
  const SegmentSimulator sim(data, {state_var});
  std::vector<ScoredCandidate> scores;
  for (size_t c = 0; c < models.size(); ++c) {
    bool diverged = false;
    const double e = sim.Error({&models[c]}, starts, steps, diverged, &segments[c]);
    scores.push_back({c, std::isfinite(e) ? e : INFINITY});
  }
  return scores;
}

// The standard error over segments of the error `mean`, whose per-segment values are `e`: 0 for
// a single segment or an error that is not finite.
double StandardError(const std::vector<double>& e, double mean) {
  double se = 0.0;
  if (e.size() > 1 && std::isfinite(mean)) {
    for (double x : e) se += (x - mean) * (x - mean);
    se = std::sqrt(se / static_cast<double>(e.size() - 1) / static_cast<double>(e.size()));
  }
  return se;
}

// The one-standard-error rule: the smallest candidate whose error is within `se` of the
// smallest error (candidate `best`'s), of those alike in size the one with the smaller error.
size_t OneStandardErrorPick(const std::vector<ScoredCandidate>& scores,
                            const std::vector<Model>& models, size_t best, double se) {
  size_t pick = best;
  for (size_t c = 0; c < models.size(); ++c)
    if (scores[c].score <= scores[best].score + se &&
        (models[c].Size() < models[pick].Size() ||
         (models[c].Size() == models[pick].Size() && scores[c].score < scores[pick].score)))
      pick = c;
  return pick;
}

// The candidates' indices, `pick` first, then the rest by error (of equal errors, the smaller
// first).
std::vector<size_t> RankOrder(const std::vector<ScoredCandidate>& scores,
                              const std::vector<Model>& models, size_t pick) {
  std::vector<ScoredCandidate> order = scores;
  std::stable_sort(order.begin(), order.end(),
                   [&](const ScoredCandidate& a, const ScoredCandidate& b) {
                     if ((a.index == pick) != (b.index == pick)) return a.index == pick;
                     return a.score < b.score ||
                            (a.score == b.score && models[a.index].Size() < models[b.index].Size());
                   });
  std::vector<size_t> ranked;
  for (const ScoredCandidate& c : order) ranked.push_back(c.index);
  return ranked;
}

// One state's candidates scored (into out.candidate_scores[s], their standard error appended to
// out.standard_errors) and ranked: the one-standard-error pick first, then the rest by error.
std::vector<size_t> RankCandidates(const SelectionData& data, int state_var,
                                   const std::vector<Model>& models,
                                   const std::vector<long>& starts, long steps, size_t s,
                                   Selection& out) {
  std::vector<std::vector<double>> segments(models.size());
  out.candidate_scores[s] = ScoreCandidates(data, state_var, models, starts, steps, segments);
  out.candidates_scored += static_cast<int>(models.size());
  const std::vector<ScoredCandidate>& scores = out.candidate_scores[s];
  size_t best = 0;
  for (size_t c = 1; c < models.size(); ++c)
    if (scores[c].score < scores[best].score) best = c;
  const double se = StandardError(segments[best], scores[best].score);
  std::vector<size_t> ranked =
      RankOrder(scores, models, OneStandardErrorPick(scores, models, best, se));
  out.standard_errors.push_back(se);
  return ranked;
}

// The rank combinations to try, at most 20: the best of each state, then one state at a time
// moved to its next best.
std::vector<std::vector<size_t>> Tries(const std::vector<std::vector<size_t>>& ranked) {
  const size_t states = ranked.size();
  std::vector<std::vector<size_t>> tries = {std::vector<size_t>(states, 0)};
  for (size_t k = 1; tries.size() < 20; ++k) {
    bool any = false;
    for (size_t s = 0; s < states && tries.size() < 20; ++s)
      if (k < ranked[s].size()) {
        std::vector<size_t> rank(states, 0);
        rank[s] = k;
        tries.push_back(rank);
        any = true;
      }
    if (!any) break;
  }
  return tries;
}

// out.chosen: the first of the tries whose whole model free-runs the training record within
// the bounds, else (out.free_run_diverged) the first; out.rejected_for_divergence counts the
// tries that diverged before it.
void ChooseFreeRunning(const SelectionData& data, const std::vector<int>& state_vars,
                       const std::vector<StateCandidates>& states,
                       const std::vector<std::vector<size_t>>& ranked, Selection& out) {
  const SegmentSimulator joint(data, state_vars);
  const std::vector<std::vector<size_t>> tries = Tries(ranked);
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
    joint.FreeRunError(models, diverged);
    if (!diverged) {
      out.chosen = combo;
      out.free_run_diverged = false;
      break;
    }
    ++out.rejected_for_divergence;
  }
}

}  // namespace

Selection SelectModels(const SelectionData& data, const std::vector<StateCandidates>& states) {
  const long rows = data.t.size();
  const std::vector<int> state_vars = StateVariables(data, states);
  if (data.validation_begin < 0 || rows - data.validation_begin < 2)
    throw InputError("gp model selection: the validation part has fewer than 2 samples");

  // Segments of the horizon over the validation rows (one shorter segment when it is short).
  const double dt = MedianInterval(data.t);
  const long span = rows - 1 - data.validation_begin;
  const long steps = std::clamp<long>(std::lround(data.horizon_s / dt), 1, span);
  const std::vector<long> starts =
      SegmentSimulator::Starts(data.t, data.validation_begin, rows, steps);

  Selection out;
  out.candidate_scores.resize(states.size());
  // Each state's candidates on their own: that state integrated, the others as measured, so a
  // wrong equation of one state cannot make a wrong one of another look right.
  std::vector<std::vector<size_t>> ranked(states.size());
  for (size_t s = 0; s < states.size(); ++s)
    ranked[s] = RankCandidates(data, state_vars[s], states[s].models, starts, steps, s, out);

  // The best of each, then one state at a time moved to its next best, until the whole model
  // free-runs the training record within the bounds.
  ChooseFreeRunning(data, state_vars, states, ranked, out);
  for (size_t s = 0; s < states.size(); ++s)
    out.scores.push_back(out.candidate_scores[s][out.chosen[s]].score);
  return out;
}

}  // namespace usvid::gp
