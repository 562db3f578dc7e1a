#include "metrics/free_run.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/check.h"
#include "core/error.h"
#include "core/model_view.h"
#include "effects/effect.h"
#include "effects/effect_values.h"
#include "metrics/equation_model.h"
#include "metrics/wind_aboard.h"
#include "simulation/vessel_simulator.h"

namespace usvid {

bool IsVesselModel(const nlohmann::json& model) { return ModelView(model).IsVesselModel(); }

VesselModel ParseVesselModel(const nlohmann::json& model) {
  const ModelView view(model);
  VesselModel v;
  v.simulator = &FindVessel(view.VesselModelName());
  v.params = v.simulator->Info().ParamsFrom(view.Parameters());
  for (const nlohmann::json& e : view.Effects()) v.effects.push_back(EffectFromJson(e));
  return v;
}

namespace {

// u(t - delay) under zero-order hold on the data's stamps (the first value before the start).
double HeldInput(const Dataset& d, const Eigen::VectorXd& u, double t) {
  const Eigen::VectorXd& ts = d.t();
  const auto* it = std::upper_bound(ts.data(), ts.data() + ts.size(), t);
  const Eigen::Index k = std::max<Eigen::Index>(0, (it - ts.data()) - 1);
  return u(k);
}

// A vessel model: the registered simulator with the model's parameters and effects.
FreeRun FreeRunVessel(const nlohmann::json& model, const Dataset& data, double max_step) {
  const VesselModel vessel = ParseVesselModel(model);
  const VesselInfo& info = vessel.simulator->Info();
  RunOptions options;
  options.dt = max_step;
  const SimulationResult result = vessel.simulator->RunInputs(
      data, vessel.params, ValuesOf(vessel.effects, info.inputs, info.states), options);
  FreeRun run;
  run.simulated = Dataset(data.t());
  const Eigen::Index rows = result.data.rows();
  for (const std::string& state : info.states) {
    if (!data.Has(state) || !result.data.Has(state)) continue;
    // Past a divergence the last finite value is held, as for equation models.
    Eigen::VectorXd v(data.rows());
    const Eigen::VectorXd& sim_values = result.data[state];
    for (Eigen::Index k = 0; k < data.rows(); ++k)
      v(k) = rows > 0 ? sim_values(std::min(k, rows - 1)) : data[state](0);
    run.simulated.Set(state, v);
    run.channels.push_back(state);
  }
  if (run.channels.empty())
    throw InputError("data: none of vessel " + info.name + "'s states to compare with");
  // The same per-channel bounds as an equation model's (the simulator stops only at 1e7).
  const DivergenceBounds bounds(run.channels, data);
  Eigen::VectorXd x(static_cast<Eigen::Index>(run.channels.size()));
  for (Eigen::Index k = 0; k < data.rows() && !run.diverged; ++k) {
    for (size_t i = 0; i < run.channels.size(); ++i)
      x(static_cast<Eigen::Index>(i)) = run.simulated[run.channels[i]](k);
    const int bad = bounds.Exceeded(x);
    if (bad < 0) continue;
    run.diverged = true;
    run.diverged_at_s = data.t()(k);
    run.diverged_channel = run.channels[bad];
    for (const std::string& c : run.channels) {
      Eigen::VectorXd v = run.simulated[c];
      v.tail(data.rows() - k).setConstant(v(std::max<Eigen::Index>(k - 1, 0)));
      run.simulated.Set(c, v);
    }
  }
  if (result.diverged && !run.diverged) {  // past 1e7 yet inside the bounds: a wide channel
    run.diverged = true;
    run.diverged_at_s = result.diverged_at_s;
    run.diverged_channel = "(simulator)";
  }
  return run;
}

// The data's channels for `system`'s inputs; throws InputError for a channel the data lack.
std::vector<const Eigen::VectorXd*> InputChannels(const EquationModel& system,
                                                  const Dataset& data) {
  for (const std::string& c : system.Channels())
    if (c != "north" && c != "east" && !data.Has(c)) {
      data.CheckNotText(c);
      throw InputError("data: no channel '" + c + "' for the model's free run");
    }
  std::vector<const Eigen::VectorXd*> inputs;
  for (const std::string& name : system.Inputs()) {
    if (!data.Has(name)) {
      data.CheckNotText(name);
      throw InputError("data: no channel '" + name + "' used by the model");
    }
    inputs.push_back(&data[name]);
  }
  return inputs;
}

// HeldInput within the rows [first, first + count) of `d`, as HeldInput on those rows alone.
double HeldInputIn(const Dataset& d, const Eigen::VectorXd& u, Eigen::Index first,
                   Eigen::Index count, double t) {
  const double* ts = d.t().data() + first;
  const auto* it = std::upper_bound(ts, ts + count, t);
  return u(first + std::max<Eigen::Index>(0, (it - ts) - 1));
}

// Sets the wind inputs among `u` at time t (the record's rows [first, first + count), zero-order
// hold) from the air over the ground and a free run's own heading and velocities
// `state(channel)` (WindAboard; the record's u, v where the model does not integrate them).
template <typename State, typename Inputs>
void SetWindInputs(const WindAboard& wind, const Dataset& d, Eigen::Index first, Eigen::Index count,
                   double t, State state, Inputs&& u) {
  const auto own = [&](int channel, const char* recorded) {
    return channel >= 0 ? state(channel) : HeldInputIn(d, d[recorded], first, count, t);
  };
  wind.Set(HeldInputIn(d, wind.air_north(), first, count, t),
           HeldInputIn(d, wind.air_east(), first, count, t), state(wind.psi_channel()),
           own(wind.u_channel(), "u"), own(wind.v_channel(), "v"),
           [&](int i, double value) { u(i) = value; });
}

}  // namespace

FreeRun FreeRunModel(const nlohmann::json& model, const Dataset& data, double max_step) {
  if (IsVesselModel(model)) return FreeRunVessel(model, data, max_step);
  const EquationModel system(model, [&](const std::string& c) { return data.Has(c); });
  const std::vector<std::string>& channels = system.Channels();
  const std::vector<const Eigen::VectorXd*> inputs = InputChannels(system, data);
  const WindAboard wind(data, system.Inputs(), channels);
  const auto n = static_cast<Eigen::Index>(channels.size());
  Eigen::VectorXd x(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const std::string& c = channels[i];
    x(i) = data.Has(c) && data.Get(c).IsSampled(0) ? data[c](0) : 0.0;
  }
  const DivergenceBounds bounds(channels, data);
  Eigen::VectorXd u(static_cast<Eigen::Index>(inputs.size()));
  FreeRun run;
  run.channels = channels;
  const Eigen::Index rows = data.rows();
  Eigen::MatrixXd out(rows, n);
  out.row(0) = x.transpose();
  for (Eigen::Index k = 1; k < rows; ++k) {
    if (!run.diverged) {
      const double t0 = data.t()(k - 1), span = data.t()(k) - t0;
      const int steps = std::max(1, static_cast<int>(std::ceil(span / max_step - 1e-9)));
      const double h = span / steps;
      for (int s = 0; s < steps; ++s) {
        // The input is held at its value at the step's start (zero-order hold).
        const double t = t0 + s * h;
        for (size_t i = 0; i < inputs.size(); ++i)
          u(static_cast<Eigen::Index>(i)) = HeldInput(data, *inputs[i], t - system.DelayS());
        if (wind.engaged())
          SetWindInputs(
              wind, data, 0, rows, t - system.DelayS(), [&](int c) { return x(c); },
              [&](Eigen::Index i) -> double& { return u(i); });
        system.Step(u, h, x);
      }
      if (const int bad = bounds.Exceeded(x); bad >= 0) {
        run.diverged = true;
        run.diverged_at_s = data.t()(k);
        run.diverged_channel = channels[bad];
        x = out.row(k - 1).transpose();
      }
    }
    out.row(k) = x.transpose();
  }
  run.simulated = Dataset(data.t());
  for (Eigen::Index i = 0; i < n; ++i) run.simulated.Set(channels[i], out.col(i));
  return run;
}

namespace {

// A vessel model's free run of every window, each from its own first row, stitched.
FreeRun StitchVesselWindows(const nlohmann::json& model, const Dataset& data,
                            const std::vector<Eigen::Index>& starts, double max_step) {
  const Eigen::Index rows = data.rows();
  const auto windows = static_cast<Eigen::Index>(starts.size());
  const auto end = [&](Eigen::Index j) { return j + 1 < windows ? starts[j + 1] : rows; };
  FreeRun run;
  run.simulated = Dataset(data.t());
  std::map<std::string, Eigen::VectorXd> stitched;
  for (Eigen::Index j = 0; j < windows; ++j) {
    const FreeRun part = FreeRunModel(model, data.Rows(starts[j], end(j) - starts[j]), max_step);
    run.channels = part.channels;
    run.diverged |= part.diverged;
    for (const std::string& c : part.channels) {
      auto [it, _] = stitched.try_emplace(c, Eigen::VectorXd::Constant(rows, NAN));
      it->second.segment(starts[j], end(j) - starts[j]) = part.simulated[c];
    }
  }
  for (auto& [c, values] : stitched) run.simulated.Set(c, std::move(values));
  return run;
}

// Each window's first state and divergence bounds, as FreeRunModel sees its window, and the
// longest window's rows.
struct WindowStarts {
  Eigen::ArrayXXd x;
  std::vector<DivergenceBounds> bounds;
  Eigen::Index longest = 0;
};
template <typename End>
WindowStarts StartsOfWindows(const Dataset& data, const std::vector<Eigen::Index>& starts,
                             const End& end, const std::vector<std::string>& channels) {
  const auto windows = static_cast<Eigen::Index>(starts.size());
  const auto n = static_cast<Eigen::Index>(channels.size());
  WindowStarts w{Eigen::ArrayXXd(windows, n), {}, 0};
  for (Eigen::Index j = 0; j < windows; ++j) {
    const Dataset window = data.Rows(starts[j], end(j) - starts[j]);
    for (Eigen::Index i = 0; i < n; ++i) {
      const std::string& c = channels[i];
      w.x(j, i) = window.Has(c) && window.Get(c).IsSampled(0) ? window[c](0) : 0.0;
    }
    w.bounds.emplace_back(channels, window);
    w.longest = std::max(w.longest, end(j) - starts[j]);
  }
  return w;
}

}  // namespace

FreeRun FreeRunWindows(const nlohmann::json& model, const Dataset& data,
                       const std::vector<Eigen::Index>& starts, double max_step) {
  const Eigen::Index rows = data.rows();
  const auto windows = static_cast<Eigen::Index>(starts.size());
  USVID_CHECK(
      windows > 0 && starts.front() == 0 && std::ranges::is_sorted(starts) && starts.back() < rows,
      "window starts from 0, ascending, inside the record");
  if (IsVesselModel(model)) return StitchVesselWindows(model, data, starts, max_step);
  const auto end = [&](Eigen::Index j) { return j + 1 < windows ? starts[j + 1] : rows; };
  FreeRun run;
  run.simulated = Dataset(data.t());
  const EquationModel system(model, [&](const std::string& c) { return data.Has(c); });
  const std::vector<std::string>& channels = system.Channels();
  const std::vector<const Eigen::VectorXd*> inputs = InputChannels(system, data);
  const WindAboard wind(data, system.Inputs(), channels);
  const auto n = static_cast<Eigen::Index>(channels.size());
  const auto m = static_cast<Eigen::Index>(inputs.size());
  WindowStarts first = StartsOfWindows(data, starts, end, channels);
  Eigen::ArrayXXd& x = first.x;
  const std::vector<DivergenceBounds>& bounds = first.bounds;
  const Eigen::Index longest = first.longest;
  Eigen::MatrixXd out(rows, n);
  for (Eigen::Index j = 0; j < windows; ++j) out.row(starts[j]) = x.row(j).matrix();
  std::vector<bool> diverged(static_cast<size_t>(windows), false), advance(diverged.size());
  // A window that does not advance in a step still passes through Steps (its result unused):
  // its inputs and step stay at values that are defined.
  Eigen::ArrayXXd u = Eigen::ArrayXXd::Zero(windows, m);
  Eigen::ArrayXd h = Eigen::ArrayXd::Zero(windows), t0 = Eigen::ArrayXd::Zero(windows);
  Eigen::ArrayXi steps = Eigen::ArrayXi::Zero(windows);
  Eigen::VectorXd state(n);
  const Eigen::VectorXd& t = data.t();
  for (Eigen::Index k = 1; k < longest; ++k) {
    // This row's interval in each window still running, cut into equal steps of at most max_step.
    int most = 0;
    for (Eigen::Index j = 0; j < windows; ++j) {
      steps(j) = 0;
      if (k >= end(j) - starts[j] || diverged[static_cast<size_t>(j)]) continue;
      t0(j) = t(starts[j] + k - 1);
      const double span = t(starts[j] + k) - t0(j);
      steps(j) = std::max(1, static_cast<int>(std::ceil(span / max_step - 1e-9)));
      h(j) = span / steps(j);
      most = std::max(most, steps(j));
    }
    for (int s = 0; s < most; ++s) {
      for (Eigen::Index j = 0; j < windows; ++j) {
        advance[static_cast<size_t>(j)] = s < steps(j);
        if (!advance[static_cast<size_t>(j)]) {
          h(j) = 0.0;
          continue;
        }
        // The input is held at its value at the step's start (zero-order hold).
        const double at = t0(j) + s * h(j);
        for (Eigen::Index i = 0; i < m; ++i)
          u(j, i) = HeldInputIn(data, *inputs[static_cast<size_t>(i)], starts[j],
                                end(j) - starts[j], at - system.DelayS());
        if (wind.engaged())
          SetWindInputs(
              wind, data, starts[j], end(j) - starts[j], at - system.DelayS(),
              [&](int c) { return x(j, c); }, [&](Eigen::Index i) -> double& { return u(j, i); });
      }
      system.Steps(u, h, advance, x);
    }
    for (Eigen::Index j = 0; j < windows; ++j) {
      if (k >= end(j) - starts[j]) continue;
      const Eigen::Index row = starts[j] + k;
      if (!diverged[static_cast<size_t>(j)]) {
        state = x.row(j).matrix().transpose();
        if (bounds[static_cast<size_t>(j)].Exceeded(state) >= 0) {
          diverged[static_cast<size_t>(j)] = true;
          run.diverged = true;
          x.row(j) = out.row(row - 1).array();
        }
      }
      out.row(row) = x.row(j).matrix();
    }
  }
  run.channels = channels;
  for (Eigen::Index i = 0; i < n; ++i) run.simulated.Set(channels[i], out.col(i));
  return run;
}

}  // namespace usvid
