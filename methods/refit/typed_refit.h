// RefitVessel for one vessel type V (refit.h): the segment cost, the prior and the solve;
// refit_instances.h declares it, and refit_vessel.cc.in instantiates it once per vessel.
#pragma once

#include <ceres/ceres.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <optional>
#include <string_view>

#include "core/correlation_time.h"
#include "core/error.h"
#include "core/evenly_spread.h"
#include "core/records.h"
#include "core/stretches.h"
#include "methods/refit/free_information.h"
#include "methods/refit/record_weights.h"
#include "methods/refit/refit.h"
#include "methods/refit/refit_instances.h"
#include "preprocessing/smoothing_spline.h"
#include "simulation/input_track.h"
#include "simulation/open_loop.h"
#include "simulation/recorded_inputs.h"
#include "simulation/segment_length.h"
#include "simulation/vessel_simulator.h"

namespace usvid::refit {

template <Vessel V>
constexpr int DynamicStates() {
  int n = 0;
  for (std::string_view s : V::kStateNames) n += IsPositionOrHeading(s) ? 0 : 1;
  return n;
}

template <Vessel V>
constexpr std::array<int, DynamicStates<V>()> DynamicIndices() {
  std::array<int, DynamicStates<V>()> idx{};
  int n = 0;
  for (int i = 0; i < V::kStates; ++i)
    if (!IsPositionOrHeading(V::kStateNames[i])) idx[n++] = i;
  return idx;
}

// The vessel's parameters as Ceres sees them: a block of K values theta, of which parameter i
// reads theta[slot[i]] * scale[i], or `fixed[i]` when slot[i] is -1. Ceres differentiates by
// every value of the block (a Jet carries K + C + kMaxRefitTerms derivatives through each
// simulation step), so a refit of a few of a large vessel's parameters (12 of an MMG model's
// 66) gives them a block of their own: kSmallParams values when they fit (the refit of twelve
// and the hybrid's thirteen), else kCompactParams, the free ones first and the rest held. With
// more free parameters the block is the whole vector, each in its own slot. Two sizes, because a
// Jet's arithmetic grows with its length and each size is a compiled copy of the refit
// (docs/performance.md, "A refit differentiated by every parameter").
inline constexpr int kSmallParams = 16;
inline constexpr int kCompactParams = 24;

template <Vessel V>
constexpr int CompactParams() {
  return std::min(kCompactParams, V::kParams);
}

template <Vessel V>
struct ParamSlots {
  std::array<int, V::kParams> slot;
  std::array<double, V::kParams> scale, fixed;
  template <typename T>
  std::array<T, V::kParams> Expand(const T* theta) const {
    std::array<T, V::kParams> p;
    for (int i = 0; i < V::kParams; ++i)
      p[i] = slot[i] >= 0 ? theta[slot[i]] * scale[i] : T(fixed[i]);
    return p;
  }
};

// One segment: rows [first, last] of the data simulated from the free dynamic states x0 (the
// kinematic ones from the data); residuals (simulated - measured) / sd of every dynamic state
// at every sampled row after the first. The missing terms' coefficients are kappa * term_scale.
// The vessel's parameters are a block of K (ParamSlots).
template <Vessel V, int K>
struct RefitSegment {
  static constexpr int C = DynamicStates<V>();
  const InputTrack* track;
  std::vector<double> times;
  Eigen::MatrixXd measured;  // rows x C
  Eigen::Matrix<bool, Eigen::Dynamic, Eigen::Dynamic> sampled;
  std::array<double, V::kStates> first;  // the data's first row (kinematic states used)
  std::array<double, C> sd;
  ParamSlots<V> params;
  std::vector<std::shared_ptr<const ResolvedTerm>> terms;  // at most kMaxRefitTerms
  std::array<double, kMaxRefitTerms> term_scale;
  double max_step;
  bool wind_over_ground = false;  // the track's wind is the air over the ground

  int Residuals() const { return static_cast<int>((times.size() - 1) * C); }

  template <typename T>
  bool operator()(const T* theta, const T* x0, const T* kappa, T* res) const {
    constexpr int N = Plant<V>::kStates;
    constexpr auto dyn = DynamicIndices<V>();
    const std::array<T, V::kParams> p = params.Expand(theta);
    std::array<T, N> start;
    for (int i = 0; i < V::kStates; ++i) start[i] = T(first[i]);
    for (int c = 0; c < C; ++c) start[dyn[c]] = x0[c];
    const double* u0 = track->At(times[0]);  // the lag memory (unused: no effects here)
    for (int i = 0; i < V::kInputs; ++i) start[V::kStates + i] = T(u0[i]);
    OpenLoopSetup setup;
    setup.inputs = track;
    setup.times = times;
    setup.max_step = max_step;
    std::array<double, V::kInputs> limits;
    limits.fill(INFINITY);
    std::vector<T> out(times.size() * N);
    EffectValues<T> effects;
    effects.wind_over_ground = wind_over_ground;
    for (size_t j = 0; j < terms.size(); ++j)
      effects.extra_terms.push_back({terms[j], kappa[j] * term_scale[j]});
    const size_t rows = RolloutOpenLoop<V, T, Steppers::kRk4Only>(setup, start.data(), p.data(),
                                                                  effects, limits, out.data());
    int k = 0;
    for (size_t row = 1; row < times.size(); ++row) {
      const size_t use = std::min(row, rows - 1);  // a diverged run keeps its last state
      for (int c = 0; c < C; ++c, ++k)
        res[k] =
            sampled(static_cast<Eigen::Index>(row), c)
                ? (out[use * N + dyn[c]] - T(measured(static_cast<Eigen::Index>(row), c))) / sd[c]
                : T(0);
    }
    return true;
  }
};

// The prior: (theta_s - centre_s) / prior_sd for the block's values that are free parameters,
// centre_s = start_i / |start_i| (+-1: theta is the parameter over its start's size, so a
// negative start is -1).
template <int K>
struct RefitPrior {
  std::array<bool, K> free;
  std::array<double, K> centre;
  double prior_sd;
  template <typename T>
  bool operator()(const T* theta, T* res) const {
    for (int s = 0; s < K; ++s) res[s] = free[s] ? (theta[s] - centre[s]) / prior_sd : T(0);
    return true;
  }
};

namespace detail {

// The dynamic states' channels and their measurement noise sd, in DynamicIndices order.
template <Vessel V>
struct MeasuredStates {
  std::array<const Channel*, DynamicStates<V>()> channels;
  std::array<double, DynamicStates<V>()> sd;
};

// The missing terms, their coefficients kappa_j * term_scale_j (kappa from 1, or 0 for a zero
// start); the unused entries have kappa 0 and scale 1.
struct MissingTerms {
  std::vector<std::shared_ptr<const ResolvedTerm>> terms;
  std::array<double, kMaxRefitTerms> kappa{}, term_scale;
};

// The free parameters: `requested`, or when empty the vessel's kRefitParams (else its damping
// and resistance groups). Throws InputError for a name the vessel does not have.
template <Vessel V>
std::array<bool, V::kParams> FreeParameters(const VesselInfo& info,
                                            const std::vector<std::string>& requested) {
  std::array<bool, V::kParams> free{};
  std::vector<std::string> names = requested;
  if (names.empty()) {
    if constexpr (requires { V::kRefitParams; }) {
      for (std::string_view n : V::kRefitParams) names.emplace_back(n);
    } else {
      for (int i = 0; i < V::kParams; ++i)
        if (V::kParamGroups[i] == ParamGroup::kDamping ||
            V::kParamGroups[i] == ParamGroup::kResistance)
          names.emplace_back(V::kParamNames[i]);
    }
  }
  for (const std::string& n : names) {
    const auto it = std::find(info.params.begin(), info.params.end(), n);
    if (it == info.params.end())
      throw InputError("--refit-params: vessel " + info.name + " has no parameter '" + n + "'");
    if constexpr (requires { V::kFixedFrom; }) {
      if (it - info.params.begin() >= V::kFixedFrom)
        throw InputError("--refit-params: '" + n + "' is a particular of vessel " + info.name +
                         ", fixed (docs/model.md#vessel-files)");
    }
    free[it - info.params.begin()] = true;
  }
  return free;
}

// The sd residuals of channel `name` are divided by: the given one, or its measurement noise
// estimated from the samples, at least 0.1 % of the channel's spread (noise-free and quantised
// data). Residuals in units of the measurement noise make the data term a chi-square, so that
// the prior's relative sd means what it says.
inline double ResidualSd(const Channel& channel, Eigen::Index rows, const std::string& name,
                         const RefitOptions& o) {
  std::vector<double> samples;
  for (Eigen::Index k = 0; k < rows; ++k)
    if (channel.IsSampled(k)) samples.push_back(channel.Value(k));
  const Eigen::Map<const Eigen::VectorXd> y(samples.data(),
                                            static_cast<Eigen::Index>(samples.size()));
  const double spread = y.size() > 1 ? std::sqrt((y.array() - y.mean()).square().mean()) : 1.0;
  const auto given = o.noise_sd.find(name);
  const double noise = given != o.noise_sd.end() ? given->second
                       : y.size() >= 16          ? EstimateNoiseSd(y)
                                                 : 0.0;
  return std::max({noise, 1e-3 * spread, 1e-12});
}

// Each dynamic state's channel (its name appended to result->channels) and residual sd.
// Throws InputError when one is missing.
template <Vessel V>
MeasuredStates<V> MeasureStates(const VesselInfo& info, const Dataset& data, const RefitOptions& o,
                                RefitResult* result) {
  constexpr int C = DynamicStates<V>();
  constexpr auto dyn = DynamicIndices<V>();
  MeasuredStates<V> states;
  for (int c = 0; c < C; ++c) {
    const std::string name(V::kStateNames[dyn[c]]);
    states.channels[c] = data.Find(name);
    if (states.channels[c] == nullptr)
      throw InputError(data.SourcePrefix() + "refit of " + info.name + " needs state column '" +
                       name + "'");
    result->channels.push_back(name);
    states.sd[c] = ResidualSd(*states.channels[c], data.rows(), name, o);
  }
  return states;
}

// The missing terms resolved, their coefficients split into kappa and scale. Throws InputError
// for too many terms or an effect that is not a missing term.
inline MissingTerms ResolveMissingTerms(const VesselInfo& info,
                                        const std::vector<Effect>& effects) {
  if (effects.size() > static_cast<size_t>(kMaxRefitTerms))
    throw InputError("refit: at most " + std::to_string(kMaxRefitTerms) + " missing terms, not " +
                     std::to_string(effects.size()));
  MissingTerms missing;
  missing.term_scale.fill(1.0);
  for (size_t j = 0; j < effects.size(); ++j) {
    if (effects[j].kind != EffectKind::kMissingTerm)
      throw InputError("refit: effect " + EffectLabel(effects[j]) + " is not a missing term");
    missing.terms.push_back(ResolveTerm(effects[j], info.states, info.inputs));
    const double c = effects[j].at("coefficient");
    missing.term_scale[j] = c != 0.0 ? std::abs(c) : 1.0;
    missing.kappa[j] = c / missing.term_scale[j];
  }
  return missing;
}

// Segments of segment_s seconds as rows [first, last] (the last may be shorter; at least two
// rows each), none across a gap of the log (core/stretches.h). Throws InputError for fewer
// than two rows.
inline std::vector<std::pair<Eigen::Index, Eigen::Index>> SegmentBounds(const Dataset& data,
                                                                        double segment_s) {
  std::vector<std::pair<Eigen::Index, Eigen::Index>> bounds;
  const Eigen::VectorXd& t = data.t();
  const double gap = GapLimit(t, kRawGapFactor);
  for (Eigen::Index a = 0; a + 1 < data.rows();) {
    if (t(a + 1) - t(a) > gap) {  // the next segment starts after the gap
      ++a;
      continue;
    }
    Eigen::Index b = a + 1;
    while (b + 1 < data.rows() && t(b + 1) - t(a) <= segment_s && t(b + 1) - t(b) <= gap) ++b;
    bounds.emplace_back(a, b);
    a = b;
  }
  if (bounds.empty()) throw InputError(data.SourcePrefix() + "refit needs at least two rows");
  return bounds;
}

// At most max_rows rows' worth of `bounds` (all when max_rows is 0), spread evenly over them.
inline std::vector<std::pair<Eigen::Index, Eigen::Index>> SpreadSegments(
    std::vector<std::pair<Eigen::Index, Eigen::Index>> bounds, long max_rows) {
  if (max_rows <= 0) return bounds;
  const Eigen::Index rows = bounds.back().second - bounds.front().first + 1;
  const double per_segment = static_cast<double>(rows) / static_cast<double>(bounds.size());
  std::vector<std::pair<Eigen::Index, Eigen::Index>> kept;
  for (const long j :
       EvenlySpread(static_cast<long>(bounds.size()),
                    std::max<long>(1, std::lround(static_cast<double>(max_rows) / per_segment))))
    kept.push_back(bounds[static_cast<size_t>(j)]);
  return kept;
}

// The segment of rows [a, b]: its times, measurements and first row, with the scales.
template <Vessel V, int K>
RefitSegment<V, K>* NewSegment(const Dataset& data, const InputTrack& track, Eigen::Index a,
                               Eigen::Index b, double dt, const MeasuredStates<V>& states,
                               const ParamSlots<V>& params, const MissingTerms& missing) {
  constexpr int C = DynamicStates<V>();
  auto* seg = new RefitSegment<V, K>;
  seg->track = &track;
  seg->max_step = std::min(dt, 0.5) * 1.0000001;
  for (Eigen::Index k = a; k <= b; ++k) seg->times.push_back(data.t()(k));
  seg->measured.resize(b - a + 1, C);
  seg->sampled.resize(b - a + 1, C);
  for (Eigen::Index k = a; k <= b; ++k)
    for (int c = 0; c < C; ++c) {
      seg->sampled(k - a, c) = states.channels[c]->IsSampled(k);
      seg->measured(k - a, c) =
          states.channels[c]->IsSampled(k) ? states.channels[c]->Value(k) : 0.0;
    }
  for (int i = 0; i < V::kStates; ++i) {
    const Channel* ch = data.Find(std::string(V::kStateNames[i]));
    seg->first[i] = ch != nullptr && ch->IsSampled(a) ? ch->Value(a) : 0.0;
  }
  seg->sd = states.sd;
  seg->params = params;
  seg->terms = missing.terms;
  seg->term_scale = missing.term_scale;
  return seg;
}

// Holds constant the parameters that are not free (all of them with hold_model) and the terms'
// coefficients that are unused (all of them with hold_model).
template <int K>
void HoldFixed(const std::array<bool, K>& free, bool hold_model, size_t n_terms, double* theta,
               double* kappa, ceres::Problem* problem) {
  std::vector<int> held;
  for (int s = 0; s < K; ++s)
    if (!free[s] || hold_model) held.push_back(s);
  if (held.size() == static_cast<size_t>(K))
    problem->SetParameterBlockConstant(theta);
  else if (!held.empty())
    problem->SetManifold(theta, new ceres::SubsetManifold(K, held));
  std::vector<int> unused;
  for (int j = hold_model ? 0 : static_cast<int>(n_terms); j < kMaxRefitTerms; ++j)
    unused.push_back(j);
  if (unused.size() == static_cast<size_t>(kMaxRefitTerms))
    problem->SetParameterBlockConstant(kappa);
  else if (!unused.empty())
    problem->SetManifold(kappa, new ceres::SubsetManifold(kMaxRefitTerms, unused));
}

// Solves the problem, recording how it went (termination, costs, iterations, time) in `result`.
inline void SolveRefit(const RefitOptions& o, ceres::Problem* problem, RefitResult* result) {
  ceres::Solver::Options so;
  so.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  so.max_num_iterations = o.max_iterations;
  so.num_threads = std::max(1, o.threads);
  // A held-out score (hold_model) fits only the segments' initial states, a cheap, well-posed
  // problem: it keeps the tight tolerance its scores have always had.
  so.function_tolerance = o.hold_model ? 1e-10 : o.function_tolerance;
  ceres::Solver::Summary summary;
  const auto t0 = std::chrono::steady_clock::now();
  ceres::Solve(so, problem, &summary);
  result->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  result->termination = ceres::TerminationTypeToString(summary.termination_type) +
                        std::string(": ") + summary.message;
  result->converged = summary.termination_type == ceres::CONVERGENCE;
  result->initial_cost = summary.initial_cost;
  result->final_cost = summary.final_cost;
  result->iterations = static_cast<int>(summary.iterations.size());
}

// The integrated autocorrelation time of the segments' residuals (the first `residuals`; the
// prior's are last), over `channels` interleaved channels.
inline double SegmentCorrelationTime(ceres::Problem& problem, int residuals, int channels) {
  std::vector<double> r;
  problem.Evaluate(ceres::Problem::EvaluateOptions(), nullptr, &r, nullptr, nullptr);
  r.resize(static_cast<size_t>(residuals));
  return CorrelationTime(
      Eigen::Map<const Eigen::VectorXd>(r.data(), static_cast<Eigen::Index>(r.size())), channels);
}

// The parameters' slots in a block of K, scaled by their starts: `theta` the block's starting
// values, `block_free` which of them are free parameters.
template <Vessel V, int K>
ParamSlots<V> FillSlots(const std::vector<double>& start, const std::array<bool, V::kParams>& free,
                        std::array<double, K>& theta, std::array<bool, K>& block_free) {
  ParamSlots<V> slots;
  int next = 0;
  for (int i = 0; i < V::kParams; ++i) {
    slots.scale[i] = start[i] != 0.0 ? std::abs(start[i]) : 1.0;
    slots.fixed[i] = start[i];
    slots.slot[i] = K == V::kParams ? i : free[i] ? next++ : -1;
    if (slots.slot[i] >= 0) {
      theta[slots.slot[i]] = start[i] / slots.scale[i];
      block_free[slots.slot[i]] = free[i];
    }
  }
  return slots;
}

// RefitTyped with the vessel's parameters in a block of K (ParamSlots): the free ones in its
// first slots when K is below V::kParams, else each parameter in its own slot.
template <Vessel V, int K>
RefitResult RefitWith(const VesselInfo& info, const Dataset& data, const std::vector<double>& start,
                      const RefitOptions& o, const std::array<bool, V::kParams>& free) {
  constexpr int C = DynamicStates<V>();
  constexpr auto dyn = DynamicIndices<V>();
  RefitResult result;
  result.names = info.params;
  result.start = start;
  for (int i = 0; i < V::kParams; ++i)
    if (free[i]) result.free.push_back(info.params[i]);
  // Data: inputs, dynamic states, their measurement noise.
  // A logged wind is met on each segment's own heading, as the free runs meet it
  // (docs/model.md#wind-on-its-own-heading).
  const InputTrack logged = RecordedInputs(data, info);
  std::optional<InputTrack> air;
  if constexpr (Plant<V>::kWindOverGround) air = WindOverGround(data, info, logged);
  const InputTrack& track = air ? *air : logged;
  const detail::MeasuredStates<V> states = detail::MeasureStates<V>(info, data, o, &result);
  if (!(o.segment_s >= 0)) throw InputError("refit: --segment must be positive (0: automatic)");
  const double segment_s = o.segment_s > 0 ? o.segment_s : AutomaticSegmentSeconds(data, info);
  result.segment_s = segment_s;
  if (!(o.prior_sd > 0)) throw InputError("refit: the prior's standard deviation must be positive");
  // theta: the block; block_free: which of its values are free parameters.
  std::array<double, K> theta{};
  std::array<bool, K> block_free{};
  const ParamSlots<V> slots = FillSlots<V, K>(start, free, theta, block_free);
  detail::MissingTerms missing = detail::ResolveMissingTerms(info, o.terms);
  const double dt = data.rows() > 1 ? data.duration() / static_cast<double>(data.rows() - 1) : 1.0;
  const auto bounds = detail::SpreadSegments(detail::SegmentBounds(data, segment_s), o.max_rows);
  std::vector<std::array<double, C>> x0(bounds.size());
  // Each segment weighs alike, or each record of a joint fit does (record_weights.h).
  const std::vector<double> weight = o.equal_records ? RecordWeights(bounds, RecordStarts(data.t()))
                                                     : std::vector<double>(bounds.size(), 1.0);
  ceres::Problem problem;
  for (size_t j = 0; j < bounds.size(); ++j) {
    const auto [a, b] = bounds[j];
    RefitSegment<V, K>* seg =
        detail::NewSegment<V, K>(data, track, a, b, dt, states, slots, missing);
    seg->wind_over_ground = air.has_value();
    for (int c = 0; c < C; ++c) x0[j][c] = seg->first[dyn[c]];
    const int residuals = seg->Residuals();
    result.residuals += residuals;
    problem.AddResidualBlock(
        new ceres::AutoDiffCostFunction<RefitSegment<V, K>, ceres::DYNAMIC, K, C, kMaxRefitTerms>(
            seg, residuals),
        weight[j] == 1.0 ? nullptr
                         : new ceres::ScaledLoss(nullptr, weight[j], ceres::TAKE_OWNERSHIP),
        theta.data(), x0[j].data(), missing.kappa.data());
  }
  problem.AddResidualBlock(new ceres::AutoDiffCostFunction<RefitPrior<K>, K, K>(
                               new RefitPrior<K>{block_free, theta, o.prior_sd}),
                           nullptr, theta.data());
  detail::HoldFixed<K>(block_free, o.hold_model, missing.terms.size(), theta.data(),
                       missing.kappa.data(), &problem);

  if (o.information_only) {
    std::vector<double*> starts;
    for (auto& x : x0) starts.push_back(x.data());
    result.information = FreeInformation(problem, theta.data(), starts, C);
    result.params = start;
    result.sd.assign(V::kParams, 0.0);
    return result;
  }
  detail::SolveRefit(o, &problem, &result);
  result.segments = static_cast<int>(bounds.size());
  if (o.hold_model)
    result.correlation_time = detail::SegmentCorrelationTime(problem, result.residuals, C);
  result.sd.assign(V::kParams, 0.0);
  const std::array<double, V::kParams> p = slots.Expand(theta.data());
  result.params.assign(p.begin(), p.end());
  result.terms = o.terms;
  for (size_t j = 0; j < missing.terms.size(); ++j)
    result.terms[j].parameters["coefficient"] = missing.kappa[j] * missing.term_scale[j];
  return result;
}

}  // namespace detail

template <Vessel V>
RefitResult RefitTyped(const VesselInfo& info, const Dataset& data,
                       const std::vector<double>& start, const RefitOptions& o) {
  const std::array<bool, V::kParams> free = detail::FreeParameters<V>(info, o.free);
  constexpr int kCompact = CompactParams<V>();
  const auto n_free = std::count(free.begin(), free.end(), true);
  if constexpr (kCompact < V::kParams) {
    if (n_free <= kSmallParams)
      return detail::RefitWith<V, kSmallParams>(info, data, start, o, free);
    if (n_free <= kCompact) return detail::RefitWith<V, kCompact>(info, data, start, o, free);
  }
  return detail::RefitWith<V, V::kParams>(info, data, start, o, free);
}

template <Vessel V>
std::map<std::string, Eigen::VectorXd> DerivativeResidualTyped(const VesselInfo& info,
                                                               const Dataset& data,
                                                               const std::vector<double>& params) {
  constexpr int C = DynamicStates<V>();
  constexpr auto dyn = DynamicIndices<V>();
  std::array<const Eigen::VectorXd*, V::kStates> x_col{};
  std::array<const Eigen::VectorXd*, V::kInputs> u_col{};
  std::array<const Eigen::VectorXd*, C> dot_col{};
  auto need = [&](const std::string& name) {
    if (!data.Has(name))
      throw InputError(data.SourcePrefix() + "the residual of " + info.name + " needs column '" +
                       name + "'");
    return &data[name];
  };
  for (int i = 0; i < V::kStates; ++i) {
    const std::string name(V::kStateNames[i]);
    x_col[i] = IsPositionOrHeading(name) ? (data.Has(name) ? &data[name] : nullptr) : need(name);
  }
  for (int i = 0; i < V::kInputs; ++i) {
    const std::string name(V::kInputNames[i]);
    // A measured disturbance (wind) the data lacks: at its neutral value, as RecordedInputs
    // holds it.
    u_col[i] = i >= CommandedInputs<V>() && !data.Has(name) ? nullptr : need(name);
  }
  for (int c = 0; c < C; ++c) dot_col[c] = need(std::string(V::kStateNames[dyn[c]]) + "_dot");
  std::map<std::string, Eigen::VectorXd> out;
  for (int c = 0; c < C; ++c) out[std::string(V::kStateNames[dyn[c]])].resize(data.rows());
  std::array<double, V::kStates> x, dx;
  std::array<double, V::kInputs> u;
  for (Eigen::Index k = 0; k < data.rows(); ++k) {
    for (int i = 0; i < V::kStates; ++i) x[i] = x_col[i] != nullptr ? (*x_col[i])(k) : 0.0;
    for (int i = 0; i < V::kInputs; ++i)
      u[i] = u_col[i] != nullptr ? (*u_col[i])(k) : info.actuation.neutral.at(i);
    V::template Derivative<double>(x.data(), u.data(), params.data(), Environment<double>{},
                                   dx.data());
    for (int c = 0; c < C; ++c)
      out[std::string(V::kStateNames[dyn[c]])](k) = (*dot_col[c])(k)-dx[dyn[c]];
  }
  return out;
}

}  // namespace usvid::refit
