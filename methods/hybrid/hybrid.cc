#include "methods/hybrid/hybrid.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "core/error.h"
#include "core/evenly_spread.h"
#include "core/parallel_for.h"
#include "core/records.h"
#include "methods/hybrid/heldout_free_run.h"
#include "preprocessing/pipeline.h"
#include "simulation/segment_length.h"
#include "simulation/vessel_simulator.h"

namespace usvid::hybrid {
namespace {

constexpr double kNoScore = std::numeric_limits<double>::infinity();

// At most max_rows rows of `data` (all when max_rows is 0), spread evenly over it.
void ThinRows(Dataset& data, long max_rows) {
  if (max_rows <= 0 || data.rows() <= max_rows) return;
  std::vector<bool> keep(static_cast<size_t>(data.rows()), false);
  for (const long k : EvenlySpread(data.rows(), max_rows)) keep[static_cast<size_t>(k)] = true;
  data.KeepRows(keep);
}

// The held-out multiple-shooting score of the vessel with `fit`'s parameters and terms.
RefitResult HeldoutScore(const VesselRef& vessel, const Dataset& heldout, const RefitResult& fit,
                         const RefitOptions& refit) {
  RefitOptions o = refit;
  o.hold_model = true;
  o.terms = fit.terms;
  return RefitVessel(vessel, heldout, fit.params, o);
}

std::vector<std::string> DynamicStatesIn(const VesselInfo& info, const Dataset& data) {
  std::vector<std::string> out;
  for (const std::string& s : info.states)
    if (!IsPositionOrHeading(s)) {
      if (!data.Has(s))
        throw InputError(data.SourcePrefix() + "--method hybrid on " + info.name +
                         " needs state column '" + s + "'");
      out.push_back(s);
    }
  return out;
}

void CheckOptions(const HybridOptions& options) {
  if (!(options.heldout > 0.0 && options.heldout < 1.0))
    throw InputError("hybrid: the held-out fraction must be in (0, 1)");
  if (options.per_state < 1) throw InputError("hybrid: at least one proposal per state");
  if (options.search_rows < 0) throw InputError("hybrid: search_rows must be >= 0");
  if (options.max_terms < 0 || options.max_terms > kMaxRefitTerms)
    throw InputError("hybrid: at most " + std::to_string(kMaxRefitTerms) + " terms");
  if (!(options.set_aside_cosine >= 0.0 && options.set_aside_cosine <= 1.0))
    throw InputError("hybrid: set_aside_cosine must be in [0, 1]");
  if (!(options.critical_ratio >= 0.0))
    throw InputError("hybrid: the critical likelihood ratio must be >= 0");
}

// The refit the selection runs: no terms yet, the segment length the record's own, and
// search_rows rows a fit. The selection fits and scores proposals side by side, two at a time on
// 2 cores: each of its fits and scores takes search_rows, by default half of max_rows (whatever
// the threads, so the numbers do not depend on them), so that by default the selection holds no
// more than the final fit on the whole record.
RefitOptions SelectionRefit(const HybridOptions& options, const VesselInfo& info,
                            const Dataset& data) {
  RefitOptions refit = options.refit;
  refit.terms.clear();
  refit.hold_model = false;
  if (refit.segment_s == 0.0) refit.segment_s = AutomaticSegmentSeconds(data, info);
  if (options.search_rows > 0)
    refit.max_rows = options.search_rows;
  else if (refit.max_rows > 0)
    refit.max_rows = std::max<long>(1, refit.max_rows / 2);
  return refit;
}

// Proposals from the derivative residual on the first part, into result.proposals (those with
// a freed coefficient's own shape set aside on request). The residual is regressed on the
// library at rows spread over the first part (at most the refits' max_rows): the library has
// tens of columns, and on a long log it was the largest block held.
void ProposeFromResidual(const VesselRef& vessel, const VesselInfo& info, const Dataset& first,
                         const std::vector<std::string>& states, const std::vector<double>& start,
                         const RefitResult& vessel_fit, long max_rows, const HybridOptions& options,
                         HybridResult& result) {
  PreparedData prepared = Preprocess(first, states, info.InputsIn(first), PreprocessOptions{});
  ThinRows(prepared.data, max_rows);
  // A speed-scaled model's hull and rudder forces are U^2 f(v', r', rudder angle); its
  // propeller has a model of its own (thrust from the advance ratio), so the propeller's
  // revolutions are not in the library.
  const Actuation& a = info.actuation;
  const bool scaled = info.speed_scaled_forces && a.speed_is_surge;
  const std::vector<std::string> library_inputs =
      !scaled          ? info.CommandedInputs()
      : a.yaw_is_angle ? std::vector<std::string>{info.inputs[a.yaw_input]}
                       : std::vector<std::string>{};
  // From the residual of the vessel as given and of the refitted one: a refit that bends its
  // coefficients towards a missing term hides it (odin3dof with r' += 0.05 |v| v: from the
  // given vessel's residual |v| v explains 99.9 %; after the refit, no single term stands out).
  for (const std::vector<double>* params : {&start, &vessel_fit.params})
    for (TermProposal& p : ProposeTerms(
             prepared.data, DerivativeResidual(vessel, prepared.data, *params), library_inputs,
             options.per_state, scaled ? info.states[a.speed_state] : std::string()))
      if (std::none_of(result.proposals.begin(), result.proposals.end(),
                       [&](const TermProposal& q) { return SameEffect(q.term, p.term); }))
        result.proposals.push_back(std::move(p));
  // A proposal with a freed coefficient's own shape would only move that coefficient past its
  // prior (free_coefficient_shape.h): each is told its closest, and set aside on request.
  const std::vector<CoefficientShape> shapes =
      ClosestFreeCoefficient(vessel, prepared.data, vessel_fit.names, vessel_fit.params,
                             vessel_fit.free, result.proposals);
  std::vector<TermProposal> kept;
  for (size_t i = 0; i < shapes.size(); ++i) {
    if (options.set_aside_cosine > 0.0 && shapes[i].cosine >= options.set_aside_cosine)
      result.set_aside.emplace_back(result.proposals[i], shapes[i]);
    else {
      kept.push_back(result.proposals[i]);
      result.proposal_shapes.push_back(shapes[i]);
    }
  }
  result.proposals = std::move(kept);
}

// The record's two parts and what the selection compares against.
struct SelectionData {
  const VesselRef& vessel;
  const Dataset& first;
  const Dataset& heldout;
  const std::vector<double>& start;
  const std::vector<std::string>& states;
};

// Forward selection by held-out simulation: each round refits every proposal not yet taken
// beside the terms chosen, and keeps the best by multiple shooting among those whose held-out
// free runs hold and are no worse, when its likelihood ratio passes the critical one. Fills
// result.rounds, heldout_error and free_run_error; returns the terms chosen, with the
// coefficients fitted so far.
std::vector<Effect> SelectTerms(const SelectionData& d, const RefitOptions& refit,
                                const HybridOptions& options, HybridResult& result) {
  std::vector<Effect> chosen;
  double error = result.vessel_heldout_error;
  double free_run_error = result.vessel_free_run_error;
  const int n = static_cast<int>(result.proposals.size());
  std::vector<bool> taken(static_cast<size_t>(n), false);
  for (int round = 0; round < options.max_terms; ++round) {
    SelectionRound r;
    r.heldout_error.assign(static_cast<size_t>(n), kNoScore);
    r.free_run_error.assign(static_cast<size_t>(n), kNoScore);
    std::vector<RefitResult> fits(static_cast<size_t>(n));
    // In a suite the other threads, once out of cells, take proposals too (core/parallel_for.h).
    ParallelFor(n, options.refit.threads, [&](int j) {
      if (taken[j]) return;
      try {
        RefitOptions o = refit;
        o.threads = 1;
        o.terms = chosen;
        o.terms.push_back(result.proposals[j].term);
        fits[j] = RefitVessel(d.vessel, d.first, d.start, o);
        const double e = MeanSquaredError(HeldoutScore(d.vessel, d.heldout, fits[j], o));
        if (std::isfinite(e)) r.heldout_error[j] = e;
        r.free_run_error[j] =
            HeldoutFreeRunError(d.vessel, d.heldout, fits[j].params, fits[j].terms, d.states);
      } catch (const std::exception&) {
        // A proposal whose fit fails is not chosen (its error stays infinite).
      }
    });
    int best = -1;
    for (int j = 0; j < n; ++j)
      if (std::isfinite(r.heldout_error[j]) && std::isfinite(r.free_run_error[j]) &&
          r.free_run_error[j] <= free_run_error &&
          (best < 0 || r.heldout_error[j] < r.heldout_error[best]))
        best = j;
    if (best >= 0 && r.heldout_error[best] > 0.0)
      r.likelihood_ratio = result.effective_samples * std::log(error / r.heldout_error[best]);
    if (best >= 0 && r.likelihood_ratio > options.critical_ratio) {
      r.chosen = best;
      taken[best] = true;
      chosen = fits[best].terms;  // the coefficients fitted so far start the next round
      error = r.heldout_error[best];
      free_run_error = r.free_run_error[best];
    }
    result.rounds.push_back(r);
    if (r.chosen < 0) break;
  }
  result.heldout_error = error;
  result.free_run_error = free_run_error;
  return chosen;
}

}  // namespace

HybridResult IdentifyHybrid(const VesselRef& vessel, const Dataset& data,
                            const std::vector<double>& start, const HybridOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  CheckOptions(options);
  const VesselInfo& info = vessel.Info();
  const std::vector<std::string> states = DynamicStatesIn(info, data);
  const RefitOptions refit = SelectionRefit(options, info, data);
  // Each record fits and judges (core/records.h): cut at the share of the rows alone, eight
  // joined runs (random, turning, zig-zag) were fitted on the random runs and turns and judged
  // on the zig-zags.
  const RecordSplit parts = SplitEachRecord(data, options.heldout, 16, std::string(kMethodName));
  const Dataset &first = parts.first, &heldout = parts.last;

  HybridResult result;
  const RefitResult vessel_fit = RefitVessel(vessel, first, start, refit);
  const RefitResult vessel_score = HeldoutScore(vessel, heldout, vessel_fit, refit);
  result.vessel_heldout_error = MeanSquaredError(vessel_score);
  result.effective_samples = vessel_score.residuals / vessel_score.correlation_time;
  result.vessel_free_run_error =
      HeldoutFreeRunError(vessel, heldout, vessel_fit.params, {}, states);

  ProposeFromResidual(vessel, info, first, states, start, vessel_fit, refit.max_rows, options,
                      result);
  const std::vector<Effect> chosen =
      SelectTerms({vessel, first, heldout, start, states}, refit, options, result);

  RefitOptions final_options = refit;
  final_options.terms = chosen;
  final_options.max_rows = options.refit.max_rows;
  result.fit = RefitVessel(vessel, data, start, final_options);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

}  // namespace usvid::hybrid
