#include "preprocessing/actuator_dynamics.h"

#include <ceres/ceres.h>

#include <Eigen/Cholesky>
#include <Eigen/QR>
#include <algorithm>
#include <memory>
#include <nlopt.hpp>

#include "core/error.h"

namespace usvid {
namespace {

// The simulation's parameters, in this order; q = 1 / rate_max^2 (0: no rate limit).
enum { kGain, kOffset, kTau, kQ, kDelay, kParams };
using Params = std::array<double, kParams>;

constexpr int kMinSamples = 20;
constexpr int kDelaySteps = 20;  // the profile's delay steps up to max_delay_s, at most
// Ceres's relative function tolerance in the delay profile (ranking) and in the final fits.
constexpr double kLooseTolerance = 1e-6, kTightTolerance = 1e-12;
constexpr int kProfileIterations = 6;  // enough to rank the delays

// A command held from each of its samples (the first also before it), and the times at which
// the state is simulated: from y0 at t[0].
struct Record {
  std::vector<double> command_t, command;
  std::vector<double> t;
  std::vector<double> y;  // the measured state at t (empty when only simulating)
  double y0 = 0.0;
};

// asinh(z) for z >= 0, accurate for small z.
template <typename T>
T Asinh(const T& z) {
  using std::log1p;
  using std::sqrt;
  return log1p(z + z * z / (1.0 + sqrt(1.0 + z * z)));
}

// y after h seconds with y_cmd held, exactly: with a = |y_cmd - y| sqrt(q) / tau, sinh(a)
// decays as exp(-t / tau).
template <typename T>
T Step(const T& y, const T& y_cmd, const T& h, const T& tau, const T& q) {
  using std::exp;
  using std::sinh;
  using std::sqrt;
  const T e = y_cmd - y;
  const T decay = exp(-h / tau);
  const T a2 = e * e * q / (tau * tau);
  // Near the set point asinh(sinh(a) k) / a = k + a^2 (k - k^3) / 6 + O(a^4): smooth in q at 0.
  if (a2 < 1e-8) return y_cmd - e * (decay + a2 * (decay - decay * decay * decay) / 6.0);
  const T a = sqrt(a2);
  const T left = a - h / tau;  // log(2 sinh(a) k) for large a
  T remaining;                 // asinh(sinh(a) k), |e| after h in units of tau rate_max
  if (a >= 20.0 && left > 20.0) {
    remaining = left;  // slewing all the way: |e| shrinks by rate_max h
  } else {
    remaining = Asinh(a < 20.0 ? sinh(a) * decay : 0.5 * exp(left));
  }
  const T error_after = remaining * tau / sqrt(q);
  return e < 0.0 ? y_cmd + error_after : y_cmd - error_after;
}

// The index of the command in force at `time` - delay, from index j on.
template <typename T>
size_t InForce(const Record& r, size_t j, const T& delay, double time) {
  while (j + 1 < r.command_t.size() && r.command_t[j + 1] + delay <= time) ++j;
  return j;
}

// The state at the record's times (out[0] = y0) under the command delayed by p[kDelay].
template <typename T>
void Simulate(const Record& r, const T* p, T* out) {
  if (r.t.empty()) return;
  const T& delay = p[kDelay];
  auto y_cmd = [&](size_t j) { return p[kOffset] + p[kGain] * r.command[j]; };
  size_t j = InForce(r, 0, delay, r.t[0]);
  T time(r.t[0]), y(r.y0);
  out[0] = y;
  for (size_t k = 1; k < r.t.size(); ++k) {
    for (size_t next = InForce(r, j, delay, r.t[k]); j < next; ++j) {
      const T change = r.command_t[j + 1] + delay;
      y = Step(y, y_cmd(j), change - time, p[kTau], p[kQ]);
      time = change;
    }
    y = Step(y, y_cmd(j), r.t[k] - time, p[kTau], p[kQ]);
    time = T(r.t[k]);
    out[k] = y;
  }
}

// Simulated minus measured state after the first sample.
struct SimulationError {
  const Record* r;
  template <typename T>
  bool operator()(const T* gain, const T* offset, const T* tau, const T* q, const T* delay,
                  T* residual) const {
    const std::array<T, kParams> p = {*gain, *offset, *tau, *q, *delay};
    std::vector<T> y(r->t.size());
    Simulate(*r, p.data(), y.data());
    for (size_t k = 1; k < y.size(); ++k) residual[k - 1] = y[k] - r->y[k];
    return true;
  }
};

ceres::CostFunction* NewCost(const Record& r) {
  return new ceres::AutoDiffCostFunction<SimulationError, ceres::DYNAMIC, 1, 1, 1, 1, 1>(
      new SimulationError{&r}, static_cast<int>(r.t.size()) - 1);
}

double SquaredError(const Record& r, const Params& p) {
  std::vector<double> y(r.t.size());
  Simulate(r, p.data(), y.data());
  double sum = 0.0;
  for (size_t k = 1; k < y.size(); ++k) sum += (y[k] - r.y[k]) * (y[k] - r.y[k]);
  return sum;
}

struct Fit {
  Params p{};
  double cost = INFINITY;  // half the sum of squared residuals
  bool rate_free = true;
};

// Gain, offset, tau and (when rate_free) q by Ceres from p, the delay held; q = 0 otherwise.
// `tolerance` is Ceres's relative function tolerance, `iterations` its iteration limit.
Fit FitAtDelay(const Record& r, Params p, bool rate_free, double min_tau, double tolerance,
               int iterations = 100) {
  if (!rate_free) p[kQ] = 0.0;
  p[kTau] = std::max(p[kTau], min_tau);
  ceres::Problem problem;
  problem.AddResidualBlock(NewCost(r), nullptr, &p[kGain], &p[kOffset], &p[kTau], &p[kQ],
                           &p[kDelay]);
  problem.SetParameterLowerBound(&p[kTau], 0, min_tau);
  problem.SetParameterLowerBound(&p[kQ], 0, 0.0);
  problem.SetParameterBlockConstant(&p[kDelay]);
  if (!rate_free) problem.SetParameterBlockConstant(&p[kQ]);
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = iterations;
  options.function_tolerance = tolerance;
  options.parameter_tolerance = 1e-2 * tolerance;
  options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  return {p, summary.final_cost, rate_free};
}

// The time constant of the smallest simulation error on a doubling grid from dt / 2, the
// other parameters held.
Params ScanTimeConstant(const Record& r, Params p, double dt) {
  Params best = p;
  double best_error = INFINITY;
  for (p[kTau] = 0.5 * dt; p[kTau] < 100.0; p[kTau] *= 2.0) {
    const double error = SquaredError(r, p);
    if (error < best_error) best_error = error, best = p;
  }
  return best;
}

// The best of the fits at the delays {0, step, ...} up to max_delay, each from p: the cost
// profile over the delay, which follows the valley where a longer delay trades for a shorter
// time constant.
Fit ProfileDelay(const Record& r, const Params& p, double step, double max_delay, double min_tau) {
  Fit best;
  for (int i = 0; i * step <= max_delay + 1e-9; ++i) {
    Params start = p;
    start[kDelay] = i * step;
    const Fit fit = FitAtDelay(r, start, true, min_tau, kLooseTolerance, kProfileIterations);
    if (fit.cost < best.cost) best = fit;
  }
  return best;
}

// The delay within one scan step of `start`'s minimising the cost of FitAtDelay, by NLopt's
// Sbplx, each fit from `start`'s parameters (so the cost is a function of the delay alone).
Fit RefineDelay(const Record& r, const Fit& start, double step, double max_delay, double min_tau,
                double xtol) {
  const double low = std::max(0.0, start.p[kDelay] - step);
  const double high = std::min(max_delay, start.p[kDelay] + step);
  if (!(high > low)) return FitAtDelay(r, start.p, start.rate_free, min_tau, kTightTolerance);
  struct Search {
    const Record& r;
    const Fit& start;
    double min_tau;
    Fit best;
  } search{r, start, min_tau, {}};
  auto cost = [](const std::vector<double>& x, std::vector<double>&, void* data) {
    auto* s = static_cast<Search*>(data);
    Params p = s->start.p;
    p[kDelay] = x[0];
    const Fit fit = FitAtDelay(s->r, p, s->start.rate_free, s->min_tau, kTightTolerance);
    if (fit.cost < s->best.cost) s->best = fit;
    return fit.cost;
  };
  nlopt::opt opt(nlopt::LN_SBPLX, 1);
  opt.set_lower_bounds(low);
  opt.set_upper_bounds(high);
  opt.set_min_objective(cost, &search);
  opt.set_initial_step(0.25 * step);
  opt.set_xtol_abs(xtol);
  opt.set_ftol_rel(1e-10);
  opt.set_maxeval(20);
  std::vector<double> x = {std::clamp(start.p[kDelay], low, high)};
  double f = 0.0;
  try {
    opt.optimize(x, f);
  } catch (const std::exception&) {
    // NLopt stops on round-off; the best fit seen is kept.
  }
  return std::isfinite(search.best.cost)
             ? search.best
             : FitAtDelay(r, start.p, start.rate_free, min_tau, kTightTolerance);
}

// Standard deviations of the free parameters, sqrt(diag((J^T J)^-1) s^2) with s^2 the residual
// variance; NaN for held parameters or a singular J^T J.
Params Deviations(const Record& r, const Fit& fit) {
  Params sd;
  sd.fill(NAN);
  const std::unique_ptr<ceres::CostFunction> cost(NewCost(r));
  const int n = cost->num_residuals();
  Eigen::VectorXd residual(n);
  Eigen::MatrixXd jacobian(n, kParams);  // column-major: one column per parameter
  std::array<const double*, kParams> blocks;
  std::array<double*, kParams> columns;
  for (int i = 0; i < kParams; ++i) {
    blocks[i] = &fit.p[i];
    columns[i] = jacobian.col(i).data();
  }
  if (!cost->Evaluate(blocks.data(), residual.data(), columns.data())) return sd;
  std::vector<int> free = {kGain, kOffset, kTau, kDelay};
  if (fit.rate_free) free.push_back(kQ);
  const auto m = static_cast<int>(free.size());
  Eigen::MatrixXd used(n, m);
  for (int c = 0; c < m; ++c) used.col(c) = jacobian.col(free[c]);
  const Eigen::LDLT<Eigen::MatrixXd> ldlt(used.transpose() * used);
  if (ldlt.info() != Eigen::Success || !(ldlt.vectorD().array() > 0).all()) return sd;
  const Eigen::MatrixXd covariance = ldlt.solve(Eigen::MatrixXd::Identity(m, m));
  const double s2 = residual.squaredNorm() / std::max(1, n - m);
  for (int c = 0; c < m; ++c) sd[free[c]] = std::sqrt(std::max(0.0, covariance(c, c) * s2));
  return sd;
}

// Largest |y_cmd - y| / (tau rate_max) at the record's times.
double PeakSaturation(const Record& r, const Params& p) {
  std::vector<double> y(r.t.size());
  Simulate(r, p.data(), y.data());
  double peak = 0.0;
  for (size_t k = 0, j = 0; k < y.size(); ++k) {
    j = InForce(r, j, p[kDelay], r.t[k]);
    peak = std::max(peak, std::abs(p[kOffset] + p[kGain] * r.command[j] - y[k]));
  }
  return peak * std::sqrt(p[kQ]) / p[kTau];
}

// Gain and offset by least squares of the state on the command over the last third of each
// stretch where the command holds (from max_delay after it starts, so the state has seen it);
// over all samples when the stretches give fewer than two levels.
std::pair<double, double> SteadyGainOffset(const Record& r, double max_delay) {
  std::vector<double> u, y;
  for (size_t j = 0, end = 1; j < r.command.size(); j = end, end = j + 1) {
    while (end < r.command.size() && r.command[end] == r.command[j]) ++end;
    const double stop = end < r.command.size() ? r.command_t[end] : r.t.back();
    const double from = r.command_t[j] + max_delay;
    const auto first = std::lower_bound(r.t.begin(), r.t.end(), from + 2.0 / 3.0 * (stop - from));
    const auto last = std::lower_bound(r.t.begin(), r.t.end(), stop);
    if (from >= stop || first >= last) continue;
    double sum = 0.0;
    for (auto it = first; it != last; ++it) sum += r.y[it - r.t.begin()];
    u.push_back(r.command[j]);
    y.push_back(sum / static_cast<double>(last - first));
  }
  if (u.size() < 2 ||
      *std::max_element(u.begin(), u.end()) == *std::min_element(u.begin(), u.end())) {
    u.clear();
    y = r.y;
    for (size_t k = 0, j = 0; k < r.t.size(); ++k)
      u.push_back(r.command[j = InForce(r, j, 0.0, r.t[k])]);
  }
  Eigen::MatrixXd a(u.size(), 2);
  a.col(0) = Eigen::Map<const Eigen::VectorXd>(u.data(), static_cast<Eigen::Index>(u.size()));
  a.col(1).setOnes();
  const Eigen::Vector2d w = a.colPivHouseholderQr().solve(
      Eigen::Map<const Eigen::VectorXd>(y.data(), static_cast<Eigen::Index>(y.size())));
  return {w(0), w(1)};
}

// The steepest slope of the state over about half a second: the rate limit's first guess.
double SteepestSlope(const Record& r, double dt) {
  const size_t m = std::max<size_t>(1, static_cast<size_t>(std::lround(0.25 / dt)));
  double slope = 0.0;
  for (size_t k = m; k + m < r.t.size(); ++k)
    slope = std::max(slope, std::abs(r.y[k + m] - r.y[k - m]) / (r.t[k + m] - r.t[k - m]));
  return slope;
}

// The channel, with its sampled values finite; with `varying`, not constant either.
const Channel& Checked(const Dataset& data, const std::string& name, const std::string& what,
                       bool varying) {
  const Channel* c = data.Find(name);
  if (c == nullptr) {
    data.CheckNotText(name);
    throw InputError(what + "the data have no channel '" + name + "'");
  }
  double low = INFINITY, high = -INFINITY;
  for (Eigen::Index k = 0; k < data.rows(); ++k) {
    if (!c->IsSampled(k)) continue;
    if (!std::isfinite(c->Value(k)))
      throw InputError(what + "channel '" + name +
                       "' has a non-finite value at t = " + std::to_string(data.t()(k)) + " s");
    low = std::min(low, c->Value(k));
    high = std::max(high, c->Value(k));
  }
  if (!(high >= low)) throw InputError(what + "channel '" + name + "' has no samples");
  if (varying && high == low)
    throw InputError(what + "channel '" + name + "' is constant (" + std::to_string(low) +
                     "): nothing to identify");
  return *c;
}

// The record of a command (divided by u_scale) and, when given, a measured state (divided by
// y_scale) at its sampled times; without a state, all the data's times.
Record MakeRecord(const Dataset& data, const Channel& command, const Channel* state, double u_scale,
                  double y_scale) {
  Record r;
  for (Eigen::Index k = 0; k < data.rows(); ++k) {
    if (command.IsSampled(k)) {
      r.command_t.push_back(data.t()(k));
      r.command.push_back(command.Value(k) / u_scale);
    }
    if (state == nullptr || state->IsSampled(k)) r.t.push_back(data.t()(k));
    if (state != nullptr && state->IsSampled(k)) r.y.push_back(state->Value(k) / y_scale);
  }
  if (!r.y.empty()) r.y0 = r.y[0];
  return r;
}

double Range(const Channel& c) {
  double low = INFINITY, high = -INFINITY;
  for (Eigen::Index k = 0; k < c.values().size(); ++k)
    if (c.IsSampled(k)) low = std::min(low, c.Value(k)), high = std::max(high, c.Value(k));
  return high - low;
}

// The model in the data's units from a fit on values divided by u_scale and y_scale.
ActuatorModel ToModel(const Record& r, const Fit& fit, const Params& sd, double u_scale,
                      double y_scale) {
  const Params& p = fit.p;
  ActuatorModel m;
  m.delay_s = p[kDelay];
  m.gain = p[kGain] * y_scale / u_scale;
  m.offset = p[kOffset] * y_scale;
  m.time_constant_s = p[kTau];
  m.samples = static_cast<int>(r.t.size()) - 1;
  const int free = fit.rate_free ? 5 : 4;
  m.rms_error = y_scale * std::sqrt(2.0 * fit.cost / std::max(1, m.samples - free));
  m.delay_sd_s = sd[kDelay];
  m.gain_sd = sd[kGain] * y_scale / u_scale;
  m.offset_sd = sd[kOffset] * y_scale;
  m.time_constant_sd_s = sd[kTau];
  if (fit.rate_free) {
    m.rate_max = y_scale / std::sqrt(p[kQ]);
    m.rate_max_sd = 0.5 * y_scale * std::pow(p[kQ], -1.5) * sd[kQ];  // |d rate / d q| sd(q)
  }
  return m;
}

}  // namespace

ActuatorModel IdentifyActuator(const Dataset& data, const std::string& command,
                               const std::string& state, const ActuatorOptions& options) {
  const std::string what = data.SourcePrefix() + "actuator " + command + " -> " + state + ": ";
  const double max_delay = options.max_delay_s;
  if (!(max_delay >= 0.0) || !std::isfinite(max_delay))
    throw InputError(what + "max_delay_s must be finite and >= 0");
  const Channel& u = Checked(data, command, what, true);
  const Channel& x = Checked(data, state, what, true);
  const double u_scale = Range(u), y_scale = Range(x);
  const Record r = MakeRecord(data, u, &x, u_scale, y_scale);
  const double duration = r.t.back() - r.t.front();
  if (static_cast<int>(r.t.size()) < kMinSamples || duration < 4.0 * max_delay)
    throw InputError(what + "the record is too short: " + std::to_string(r.t.size()) +
                     " samples of '" + state + "' over " + std::to_string(duration) +
                     " s; needs at least " + std::to_string(kMinSamples) +
                     " samples and 4 x max_delay_s = " + std::to_string(4.0 * max_delay) + " s");
  const double dt = MedianInterval(
      Eigen::Map<const Eigen::VectorXd>(r.t.data(), static_cast<Eigen::Index>(r.t.size())));
  const double step = std::max(dt, max_delay / kDelaySteps), min_tau = 0.01 * dt;
  const double xtol = 0.02 * dt;  // the delay to a fiftieth of a sample

  // Guesses, scan, fit, profile over the delay, refinement.
  const auto [gain, offset] = SteadyGainOffset(r, max_delay);
  const double slope = SteepestSlope(r, dt);
  Params p = {gain, offset, 1.0, slope > 0.0 ? 1.0 / (slope * slope) : 0.0, 0.0};
  const Fit first = FitAtDelay(r, ScanTimeConstant(r, p, dt), true, min_tau, kLooseTolerance);
  Fit fit = RefineDelay(r, ProfileDelay(r, first.p, step, max_delay, min_tau), step, max_delay,
                        min_tau, xtol);
  Params sd = Deviations(r, fit);

  // The rate limit only where the record shows it; otherwise the linear model.
  const bool limited = fit.p[kQ] > options.rate_significance * sd[kQ] &&
                       PeakSaturation(r, fit.p) >= options.min_saturation;
  if (!limited) {
    fit.rate_free = false;
    fit.p[kQ] = 0.0;
    fit = RefineDelay(r, fit, step, max_delay, min_tau, xtol);
    sd = Deviations(r, fit);
  }
  ActuatorModel model = ToModel(r, fit, sd, u_scale, y_scale);
  model.command = command;
  model.state = state;
  return model;
}

std::vector<ActuatorModel> IdentifyWaterjetActuators(const Dataset& data,
                                                     const ActuatorOptions& options) {
  std::vector<ActuatorModel> models;
  for (const auto& [command, state] : kWaterjetActuators)
    models.push_back(IdentifyActuator(data, command, state, options));
  return models;
}

double ActuatorStep(const ActuatorModel& m, double y, double command, double h) {
  const double q = m.RateLimited() ? 1.0 / (m.rate_max * m.rate_max) : 0.0;
  return Step(y, m.offset + m.gain * command, h, m.time_constant_s, q);
}

void SimulateActuators(Dataset& data, const std::vector<ActuatorModel>& models) {
  std::vector<std::string> added;
  for (const ActuatorModel& m : models) {
    const std::string what =
        data.SourcePrefix() + "simulating actuator " + m.command + " -> " + m.state + ": ";
    Checked(data, m.command, what, false);
    if (data.Has(m.state) || std::find(added.begin(), added.end(), m.state) != added.end())
      throw InputError(what + "the data already have '" + m.state + "'");
    if (!std::isfinite(m.gain) || !std::isfinite(m.offset) || !std::isfinite(m.delay_s) ||
        m.delay_s < 0.0 || !std::isfinite(m.time_constant_s) || m.time_constant_s <= 0.0 ||
        !(m.rate_max > 0.0))
      throw InputError(what +
                       "the model needs finite gain and offset, delay_s >= 0, "
                       "time_constant_s > 0 and rate_max > 0");
    added.push_back(m.state);
  }
  for (const ActuatorModel& m : models) {
    Record r = MakeRecord(data, data.Get(m.command), nullptr, 1.0, 1.0);
    r.y0 = m.offset + m.gain * r.command[0];
    const double q = m.RateLimited() ? 1.0 / (m.rate_max * m.rate_max) : 0.0;
    const Params p = {m.gain, m.offset, m.time_constant_s, q, m.delay_s};
    Eigen::VectorXd y(data.rows());
    Simulate(r, p.data(), y.data());
    data.Set(m.state, std::move(y));
  }
}

namespace {

nlohmann::json NumberOrNull(double v) { return std::isfinite(v) ? nlohmann::json(v) : nullptr; }

// Reads the fields of one JSON object, naming the file and the field on error.
struct FieldReader {
  const nlohmann::json& object;
  const std::string& file;
  std::string where;

  [[noreturn]] void Fail(const std::string& key, const std::string& what) const {
    throw InputError(Located(file, 0, 0, where + "." + key + ": " + what));
  }
  std::string Text(const std::string& key) const {
    const auto it = object.find(key);
    if (it == object.end() || !it->is_string() || it->get<std::string>().empty())
      Fail(key, "expected a channel name");
    return it->get<std::string>();
  }
  // A finite number of at least `low` (above it when `strict`).
  double Number(const std::string& key, double low = -INFINITY, bool strict = false) const {
    const auto it = object.find(key);
    if (it == object.end() || !it->is_number()) Fail(key, "expected a number");
    const double v = it->get<double>();
    if (!std::isfinite(v) || v < low || (strict && v == low))
      Fail(key, std::isfinite(low) ? std::string("expected a finite number ") +
                                         (strict ? "> " : ">= ") + std::to_string(low)
                                   : std::string("expected a finite number"));
    return v;
  }
  // null or missing: `absent`; otherwise as Number.
  double Optional(const std::string& key, double absent, double low = -INFINITY,
                  bool strict = false) const {
    const auto it = object.find(key);
    return it == object.end() || it->is_null() ? absent : Number(key, low, strict);
  }
};

}  // namespace

nlohmann::json ActuatorModelsToJson(const std::vector<ActuatorModel>& models) {
  nlohmann::json out = nlohmann::json::array();
  for (const ActuatorModel& m : models)
    out.push_back({{"command", m.command},
                   {"state", m.state},
                   {"delay_s", m.delay_s},
                   {"gain", m.gain},
                   {"offset", m.offset},
                   {"time_constant_s", m.time_constant_s},
                   {"rate_max", NumberOrNull(m.rate_max)},
                   {"rms_error", NumberOrNull(m.rms_error)},
                   {"samples", m.samples},
                   {"sd",
                    {{"delay_s", NumberOrNull(m.delay_sd_s)},
                     {"gain", NumberOrNull(m.gain_sd)},
                     {"offset", NumberOrNull(m.offset_sd)},
                     {"time_constant_s", NumberOrNull(m.time_constant_sd_s)},
                     {"rate_max", NumberOrNull(m.rate_max_sd)}}}});
  return out;
}

std::vector<ActuatorModel> ActuatorModelsFromJson(const nlohmann::json& json,
                                                  const std::string& file) {
  if (!json.is_array())
    throw InputError(Located(file, 0, 0, "actuators: expected an array of actuator models"));
  std::vector<ActuatorModel> models;
  for (size_t i = 0; i < json.size(); ++i) {
    const FieldReader in{json[i], file, "actuators[" + std::to_string(i) + "]"};
    if (!json[i].is_object())
      throw InputError(Located(file, 0, 0, in.where + ": expected an object"));
    ActuatorModel m;
    m.command = in.Text("command");
    m.state = in.Text("state");
    m.delay_s = in.Number("delay_s", 0.0);
    m.gain = in.Number("gain");
    m.offset = in.Number("offset");
    m.time_constant_s = in.Number("time_constant_s", 0.0, true);
    if (!json[i].contains("rate_max")) in.Fail("rate_max", "expected a number or null");
    m.rate_max = in.Optional("rate_max", INFINITY, 0.0, true);
    m.rms_error = in.Optional("rms_error", NAN, 0.0);
    m.samples = static_cast<int>(in.Optional("samples", 0.0, 0.0));
    if (const auto sd = json[i].find("sd"); sd != json[i].end() && !sd->is_null()) {
      if (!sd->is_object()) in.Fail("sd", "expected an object");
      const FieldReader s{*sd, file, in.where + ".sd"};
      m.delay_sd_s = s.Optional("delay_s", NAN, 0.0);
      m.gain_sd = s.Optional("gain", NAN, 0.0);
      m.offset_sd = s.Optional("offset", NAN, 0.0);
      m.time_constant_sd_s = s.Optional("time_constant_s", NAN, 0.0);
      m.rate_max_sd = s.Optional("rate_max", NAN, 0.0);
    }
    models.push_back(std::move(m));
  }
  return models;
}

}  // namespace usvid
