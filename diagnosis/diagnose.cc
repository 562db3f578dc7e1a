#include "diagnosis/diagnose.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <utility>

#include "core/correlation_time.h"
#include "core/parallel_for.h"
#include "core/expression.h"
#include "diagnosis/residual_discovery.h"
#include "simulation/vessel_simulator.h"

namespace usvid::diagnosis {
namespace {

double Seconds(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// E of measurement noise alone: each channel's noise variance over its scale squared.
double NoiseFloor(const MeasuredData& d) {
  double sum = 0.0;
  for (size_t c = 0; c < d.channels.size(); ++c) sum += std::pow(d.noise_sd[c] / d.scale[c], 2);
  return sum / static_cast<double>(d.channels.size());
}

// The held-out residuals' correlation time (core/correlation_time.h).
double CorrelationTime(const MeasuredData& d, const Part& part, const Eigen::VectorXd& residual) {
  const auto channels = static_cast<Eigen::Index>(d.channels.size());
  return usvid::CorrelationTime(residual.head((part.end - part.begin) * channels),
                                static_cast<int>(channels));
}

// The chi-square quantile at 0.999 for k = 1, 2 degrees of freedom.
double ChiSquare999(int k) { return k == 1 ? 10.83 : 13.82; }

long SampledCount(const MeasuredData& d, const Part& part) {
  return static_cast<long>(d.sampled.middleRows(part.begin, part.end - part.begin).count());
}

// Channels of a part as the model predicts them (measured + residual x scale).
std::map<std::string, Eigen::VectorXd> ModelSeries(const MeasuredData& d, const Part& part,
                                                   const Eigen::VectorXd& residual) {
  std::map<std::string, Eigen::VectorXd> out;
  const auto channels = static_cast<Eigen::Index>(d.channels.size());
  for (Eigen::Index c = 0; c < channels; ++c) {
    Eigen::VectorXd v(part.end - part.begin);
    for (Eigen::Index k = part.begin; k < part.end; ++k)
      v(k - part.begin) =
          d.sampled(k, c)
              ? d.measured(k, c) + residual((k - part.begin) * channels + c) * d.scale[c]
              : NAN;
    out[d.channels[c]] = v;
  }
  return out;
}

// Whether the best candidate passes: its likelihood ratio beats chi-square at 0.999 and it cuts
// the reference error by at least min_reduction.
bool Passes(const Candidate& c, double reference_error, const DiagnoseOptions& options) {
  return c.likelihood_ratio >= ChiSquare999(c.parameters) &&
         c.heldout_error < (1.0 - options.min_reduction) * reference_error;
}

// Whether the commands of input i change over the record (a bucket held open does not).
bool InputMoves(const MeasuredData& d, int i) {
  const double first = d.inputs.At(d.times.front())[i];
  for (double t : d.times)
    if (d.inputs.At(t)[i] != first) return true;
  return false;
}

// The candidates: every effect of the catalogue (wind where the record has it and the vessel
// feels it), and with more than one moving command input, the
// effects that can act on one input alone on each of them (input_bias: each but the yaw input,
// which the whole-vessel input_bias already is).
std::vector<EffectSearch> Searches(const MeasuredData& d, const EffectFitter& fitter) {
  std::vector<int> moving;
  for (int i = 0; i < static_cast<int>(d.peak_command.size()); ++i)
    if (!(static_cast<size_t>(i) < d.measured_input.size() && d.measured_input[i]) &&
        InputMoves(d, i))
      moving.push_back(i);
  std::vector<EffectSearch> out;
  for (const EffectInfo& info : EffectCatalogue()) {
    if (info.kind == EffectKind::kWind && !d.wind) continue;
    out.push_back(SearchFor(info.kind, d, fitter.YawInput()));
    if (!OnInputs(info.kind) || moving.size() < 2) continue;
    for (int i : moving)
      if (info.kind != EffectKind::kInputBias || i != fitter.YawInput())
        out.push_back(SearchFor(info.kind, d, fitter.YawInput(), i));
  }
  return out;
}

// Every candidate fitted on the training part (on top of d.base) and scored on the held-out
// part against the reference error; ranked best first, look-alikes listed. k counts the
// candidate's sizes; which input a one-input effect acts on is a choice among the candidates,
// as the effect is.
std::vector<Candidate> FitCandidates(const MeasuredData& d, const EffectFitter& fitter,
                                     const std::vector<double>& params,
                                     const std::vector<EffectSearch>& searches,
                                     double reference_error, double noise_floor,
                                     double effective_samples) {
  std::vector<Candidate> candidates(searches.size());
  const double excess = reference_error - noise_floor;
  ParallelFor(static_cast<int>(searches.size()), omp_get_max_threads(), [&](int i) {
    const auto t0 = std::chrono::steady_clock::now();
    Candidate& c = candidates[i];
    const EffectSearch& search = searches[i];
    c.fit = fitter.Fit(d, d.fit, params, search);
    const Eigen::VectorXd held = fitter.Residuals(d, d.heldout, params, c.fit.effect);
    c.heldout_error = MeanSquaredError(d, d.heldout, held);
    c.heldout_fit_percent = FitPercentOf(d, d.heldout, held);
    c.parameters = search.size();
    c.likelihood_ratio = effective_samples * std::log(reference_error / c.heldout_error);
    c.score = -c.likelihood_ratio + 2.0 * search.size();
    c.explained = excess > 0 ? (reference_error - c.heldout_error) / excess : 0.0;
    c.seconds = Seconds(t0);
  });
  return candidates;
}

// The candidates ranked best first, look-alikes listed.
std::vector<Candidate> Rank(std::vector<Candidate> candidates, double reference_error) {
  // Ranked by score; where two candidates of as many sizes fit the held-out part alike (within
  // 1e-6 of the reference error: a bias on an input that enters one equation linearly is a
  // force on that equation), the whole-vessel effect goes first, the simpler account.
  auto same = [&](const Candidate& a, const Candidate& b) {
    return a.parameters == b.parameters &&
           std::abs(a.heldout_error - b.heldout_error) <= 1e-6 * reference_error;
  };
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Candidate& a, const Candidate& b) { return a.score < b.score; });
  for (size_t i = 0; i < candidates.size(); ++i)
    for (size_t j = i + 1; j < candidates.size() && same(candidates[i], candidates[j]); ++j)
      if (!candidates[i].fit.effect.inputs.empty() && candidates[j].fit.effect.inputs.empty())
        std::rotate(candidates.begin() + i, candidates.begin() + j, candidates.begin() + j + 1);
  for (Candidate& a : candidates)
    for (const Candidate& b : candidates)
      if (&a != &b && std::abs(a.heldout_error - b.heldout_error) <= 1e-3 * reference_error &&
          a.likelihood_ratio >= ChiSquare999(a.parameters) &&
          b.likelihood_ratio >= ChiSquare999(b.parameters))
        a.alike.emplace_back(EffectLabel(b.fit.effect));
  return candidates;
}

std::vector<Candidate> RankEffects(const MeasuredData& d, const EffectFitter& fitter,
                                   const std::vector<double>& params,
                                   const std::vector<EffectSearch>& searches,
                                   double reference_error, double noise_floor,
                                   double effective_samples) {
  return Rank(
      FitCandidates(d, fitter, params, searches, reference_error, noise_floor, effective_samples),
      reference_error);
}

// Each term the residual search proposes, as a missing_term search of its coefficient: the
// proposal's sum split into its terms (core/expression_terms.h), each starting at the
// coefficient the sparse regression gave it.
std::vector<EffectSearch> TermSearches(const std::vector<DiscoveredTerms>& discovered,
                                       const VesselSimulator& sim) {
  std::vector<EffectSearch> out;
  std::vector<std::pair<std::string, std::string>> seen;  // state, term
  for (const DiscoveredTerms& t : discovered)
    for (const auto& [term, coefficient] : Expression::Parse(t.expression).Terms()) {
      if (term == "1") continue;  // a constant: the catalogue's biases and forces
      if (std::find(seen.begin(), seen.end(), std::pair(t.state, term)) != seen.end()) continue;
      seen.emplace_back(t.state, term);
      Effect e{EffectKind::kMissingTerm, {{"coefficient", coefficient}}, {}, t.state, term};
      out.push_back(SearchForTerm(e, sim.Info().states, sim.Info().inputs));
    }
  return out;
}

// What a diagnosis works with throughout: the vessel's simulator and effect fitter, the nominal
// parameters, the options and the log (may be null).
struct Context {
  const VesselSimulator& sim;
  const EffectFitter& fitter;
  const std::vector<double>& params;
  const DiagnoseOptions& options;
  std::ostream* log;
};

// The model extended by the causes named so far, its held-out error and the share of the
// nominal model's excess error over the noise floor the causes explain.
struct Extension {
  MeasuredData model;
  double error = 0.0;
  double explained = 0.0;
};

// What was diagnosed: the vessel, the record and its parts, the nominal model.
Diagnosis Describe(const Dataset& data, const std::string& vessel, const Context& cx,
                   const MeasuredData& d) {
  Diagnosis out;
  out.vessel = vessel;
  out.source = data.Source();
  out.param_names = cx.sim.Info().params;
  out.params = cx.params;
  out.base_effects = cx.options.base_effects;
  out.channels = d.channels;
  out.segment_s = d.segment_s;
  out.train_s = d.times[d.train.end - 1] - d.times[d.train.begin];
  out.fit_s = d.times[d.fit.end - 1] - d.times[d.fit.begin];
  out.heldout_s = d.times[d.heldout.end - 1] - d.times[d.heldout.begin];
  return out;
}

// Beyond the catalogue: the residual search proposes terms, and each competes as a candidate,
// fitted through the simulator and scored on the held-out part like any effect. The candidates
// are ranked again, all together.
void AddDiscoveredTerms(const Context& cx, const Dataset& data, const MeasuredData& d,
                        Diagnosis& out) {
  if (cx.log) *cx.log << "diagnose: the catalogue leaves much of the residual; searching terms\n";
  if (d.fit.begin > d.train.begin) {
    // A long log: the terms are searched on the rows the effects are fitted on (--fit-rows), so
    // that SINDy's library and GP's columns stay bounded as the fits' Jacobians do.
    const Eigen::VectorXd& t = data.t();
    const double* first = std::lower_bound(t.data(), t.data() + t.size(), d.times[d.fit.begin]);
    const double* last = std::upper_bound(first, t.data() + t.size(), d.times[d.fit.end - 1]);
    out.discovered = DiscoverMissingTerms(data.Rows(first - t.data(), last - first), cx.sim,
                                          cx.fitter, cx.params, d);
  } else {
    out.discovered = DiscoverMissingTerms(data, cx.sim, cx.fitter, cx.params, d);
  }
  std::vector<Candidate> all = std::move(out.candidates);
  for (Candidate& c : FitCandidates(d, cx.fitter, cx.params, TermSearches(out.discovered, cx.sim),
                                    out.nominal_error, out.noise_floor, out.effective_samples))
    all.push_back(std::move(c));
  for (Candidate& c : all) c.alike.clear();
  out.candidates = Rank(std::move(all), out.nominal_error);
}

void LogCandidates(const Diagnosis& out, std::ostream& log) {
  for (const Candidate& c : out.candidates)
    log << "  " << EffectLabel(c.fit.effect) << ": held-out E " << c.heldout_error << " (nominal "
        << out.nominal_error << ", floor " << out.noise_floor << "), LR " << c.likelihood_ratio
        << ", " << c.seconds << " s\n";
}

// The cause found: the best candidate, added to the extended model.
void AdoptCause(const Context& cx, const Candidate& best, Extension& ext, Diagnosis& out) {
  out.cause = std::string(best.fit.effect.name());
  out.cause_effect = best.fit.effect;
  SetEffect(best.fit.effect, ext.model.base, cx.sim.Info().inputs, cx.sim.Info().states);
  ext.error = best.heldout_error;
  ext.explained = best.explained;
}

// Further causes named on the extended model while much is left: each round ranks the
// candidates on the model extended so far and adds the best while it passes.
void NameFurtherCauses(const Context& cx, const std::vector<EffectSearch>& searches, Extension& ext,
                       Diagnosis& out) {
  const double excess = out.nominal_error - out.noise_floor;
  for (int round = 1; round < cx.options.max_causes && ext.explained < cx.options.further_explained;
       ++round) {
    const std::vector<Candidate> next =
        RankEffects(ext.model, cx.fitter, cx.params, searches, ext.error, out.noise_floor,
                    out.effective_samples);
    const Candidate& c = next.front();
    if (!Passes(c, ext.error, cx.options)) break;
    FurtherCause f{c.fit.effect, c.alike,   c.likelihood_ratio,
                   c.explained,  ext.error, c.heldout_error};
    if (cx.log)
      *cx.log << "diagnose: on the extended model, " << EffectLabel(c.fit.effect) << " (LR "
              << c.likelihood_ratio << ")\n";
    out.further_causes.push_back(f);
    SetEffect(c.fit.effect, ext.model.base, cx.sim.Info().inputs, cx.sim.Info().states);
    ext.error = c.heldout_error;
    ext.explained = excess > 0 ? (out.nominal_error - ext.error) / excess : 1.0;
  }
}

// The extended model's held-out error and fit (d: the data with the extended model's base
// effects), and the held-out series: measured, nominal and extended.
void MeasureExtended(const Context& cx, const MeasuredData& d, const Eigen::VectorXd& nominal_held,
                     Diagnosis& out) {
  const Eigen::VectorXd extended_held = cx.fitter.Residuals(d, d.heldout, cx.params, std::nullopt);
  out.extended_error = MeanSquaredError(d, d.heldout, extended_held);
  out.extended_fit_percent = FitPercentOf(d, d.heldout, extended_held);
  out.heldout_error_reduction =
      out.nominal_error > 0 ? 1.0 - std::sqrt(out.extended_error / out.nominal_error) : 0.0;
  out.series.t = Eigen::Map<const Eigen::VectorXd>(d.times.data() + d.heldout.begin,
                                                   d.heldout.end - d.heldout.begin);
  for (Eigen::Index c = 0; c < static_cast<Eigen::Index>(d.channels.size()); ++c) {
    Eigen::VectorXd m = d.measured.col(c).segment(d.heldout.begin, d.heldout.end - d.heldout.begin);
    for (Eigen::Index k = 0; k < m.size(); ++k)
      if (!d.sampled(d.heldout.begin + k, c)) m(k) = NAN;
    out.series.measured[d.channels[c]] = m;
  }
  out.series.nominal = ModelSeries(d, d.heldout, nominal_held);
  out.series.extended = ModelSeries(d, d.heldout, extended_held);
}

}  // namespace

Diagnosis Diagnose(const Dataset& data, const VesselRef& vessel, const std::vector<double>& params,
                   const DiagnoseOptions& options, std::ostream* log) {
  const auto start = std::chrono::steady_clock::now();
  const VesselSimulator& sim = vessel.Simulator();
  const EffectFitter& fitter = FindEffectFitter(sim.Info().type);
  MeasuredData d = PrepareMeasuredData(data, sim, params, options.split);
  const bool wind_over_ground = d.base.wind_over_ground;  // PrepareMeasuredData's, kept
  d.base = ValuesOf(options.base_effects, sim.Info().inputs, sim.Info().states);
  d.base.wind_over_ground = wind_over_ground;
  const Context cx{sim, fitter, params, options, log};

  Diagnosis out = Describe(data, vessel.Name(), cx, d);

  // 1. Show.
  const Eigen::VectorXd nominal_held = fitter.Residuals(d, d.heldout, params, std::nullopt);
  out.nominal_error = MeanSquaredError(d, d.heldout, nominal_held);
  out.nominal_fit_percent = FitPercentOf(d, d.heldout, nominal_held);
  out.noise_floor = NoiseFloor(d);
  // The whole record's residual is a temporary: on a long log it is gone before the fits.
  out.residuals = AnalyseResiduals(d, fitter.ResetResiduals(d, d.all, params, d.base),
                                   sim.Info().inputs, d.fallback_states);
  for (const ChannelResidual& r : out.residuals)
    out.nominal_free_run_fit_percent[r.channel] = r.free_run_fit_percent;
  // The same candidates in every round: the extended model has the same inputs.
  const std::vector<EffectSearch> searches = Searches(d, fitter);
  if (log)
    *log << "diagnose: " << vessel.Name() << ", " << d.rows() << " rows, train " << out.train_s
         << " s, held out " << out.heldout_s << " s; fitting " << searches.size()
         << " candidate effects"
         << (d.fit.begin > d.train.begin
                 ? " on the training part's last " + std::to_string(std::lround(out.fit_s)) +
                       " s, scored on the " + std::to_string(std::lround(out.heldout_s)) +
                       " s after it (--fit-rows)"
                 : std::string())
         << "\n";

  // 2. Name.
  out.correlation_time = CorrelationTime(d, d.heldout, nominal_held);
  out.effective_samples = static_cast<double>(SampledCount(d, d.heldout)) / out.correlation_time;
  out.candidates = RankEffects(d, fitter, params, searches, out.nominal_error, out.noise_floor,
                               out.effective_samples);
  const bool visible = out.nominal_error > (1.0 + options.min_excess) * out.noise_floor;
  // Beyond the catalogue, when the residual is well above the noise and no effect explains most
  // of it.
  if (options.discover && visible && out.candidates.front().explained < options.min_explained)
    AddDiscoveredTerms(cx, data, d, out);
  if (log) LogCandidates(out, *log);

  const Candidate& best = out.candidates.front();
  const bool found = Passes(best, out.nominal_error, options);

  // 3. Extend and measure; name further causes on the extended model while much is left.
  // The extension takes the measured data over (the copy was the largest block on a long log):
  // only its base effects change, and the measurements it scores against are the same.
  Extension ext{std::move(d), out.nominal_error, 0.0};
  if (found) {
    AdoptCause(cx, best, ext, out);
    NameFurtherCauses(cx, searches, ext, out);
  }
  MeasureExtended(cx, ext.model, nominal_held, out);

  // What is left: the residual is well above the noise and the causes named leave much of it.
  out.unexplained = visible && (!found || ext.explained < options.min_explained);
  out.seconds = Seconds(start);
  return out;
}

}  // namespace usvid::diagnosis
