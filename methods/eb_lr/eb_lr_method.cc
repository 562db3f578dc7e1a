// `eb-lr`: Eriksen-Breivik regression of the 2-DOF high-speed model (methods/eb_lr/eb_lr.h),
// registered in methods/method_list.h.
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "core/error.h"
#include "core/parse_number.h"
#include "core/stretches.h"
#include "methods/channel_fit.h"
#include "methods/eb_lr/eb_lr.h"
#include "methods/method.h"
#include "preprocessing/pipeline.h"
#include "simulation/vessel_simulator.h"

namespace usvid {
namespace {

// eb-lr's options for the request. On the jets' surge force and yaw moment (tau_x, tau_n of
// the waterjet map, docs/baselines.md): the thrust falls with speed by the inlet's momentum drag,
// k jet_flow U; the steady windows follow the commands, which are held, not the forces, which
// slew and carry the sensors' noise; sigma_U is a quartic with a constant, which follows a
// planing hull's resistance hump over the record's speeds (the cubic without a constant does
// not), and the speed lost in a turn as r^2 and r^4 (r^2 alone put odin-hs's speed in a 20/20
// zig-zag 0.05 m/s low, a fit of U of 18-24 % against 34-49 %); U comes first, the term a record
// of few windows keeps (order auto); and m_r is the yaw inertia alone, a constant, since tau_n is
// a moment (a slope in U took m_r through zero within the data).
// The options given override these (ReadOptions).
eb_lr::EbLrOptions EbLrOptionsFor(const IdentifyRequest& o, const std::vector<std::string>& inputs,
                                  const Dataset& data) {
  eb_lr::EbLrOptions eo;
  eo.lower_order = true;
  eo.steady.full_turn_state = 1;  // a held turn steady on average over a full circle
  if (o.preprocess.forces != "waterjet" || inputs != std::vector<std::string>{"tau_x", "tau_n"})
    return eo;
  eo.thrust_loss_channel = "jet_flow";
  eo.sigma_speed_basis = {{1, 0}, {0, 0}, {2, 0}, {3, 0}, {4, 0}, {0, 2}, {0, 4}};
  eo.mass_rate_basis = {{0, 0}};
  if (o.vessel.empty()) return eo;
  const Actuation& a = o.vessel.Info().actuation;
  if (a.thrust_input < 0 || a.yaw_input < 0) return eo;
  std::vector<std::string> commands = {a.input_names[a.thrust_input], a.input_names[a.yaw_input]};
  if (data.Has(commands[0]) && data.Has(commands[1])) eo.held_inputs = std::move(commands);
  return eo;
}

// The Eriksen-Breivik 2-DOF form: speed U and rate r, driven by thrust and yaw inputs: the
// commands, or with the waterjet map the jets' surge force and yaw moment.
Channels EbLrChannels(const IdentifyRequest& o) {
  Channels c = DefaultChannels(o);
  if (!o.vessel.empty() && o.states.empty()) {
    const Actuation& a = o.vessel.Info().actuation;
    if (a.thrust_input < 0)
      throw InputError("--method eb-lr: vessel " + o.vessel.Name() + " has no thrust input");
    c.states = c.variables = {"U", "r"};
    if (o.inputs.empty())
      c.inputs =
          o.preprocess.forces == "waterjet"
              ? std::vector<std::string>{"tau_x", "tau_n"}
              : std::vector<std::string>{a.input_names[a.thrust_input], a.input_names[a.yaw_input]};
  }
  if (c.states.size() != 2 || c.inputs.size() != 2)
    throw InputError("--method eb-lr: needs --states SPEED,RATE and --inputs THRUST,YAW");
  return c;
}

// The declared options over the defaults EbLrOptionsFor chose.
void ReadOptions(const MethodOptions& m, eb_lr::EbLrOptions& eo) {
  eo.lower_order = m.Text("order") == "auto";
  eo.constant_thrust = m.Flag("constant_thrust");
  // Each key spelled where it is read (tests/architecture_test.sh finds an option's reader so).
  if (m.Has("sigma_speed_basis"))
    eo.sigma_speed_basis = eb_lr::ParseBasis(m.Text("sigma_speed_basis"), "sigma_speed_basis");
  if (m.Has("sigma_rate_basis"))
    eo.sigma_rate_basis = eb_lr::ParseBasis(m.Text("sigma_rate_basis"), "sigma_rate_basis");
  if (m.Has("mass_speed_basis"))
    eo.mass_speed_basis = eb_lr::ParseBasis(m.Text("mass_speed_basis"), "mass_speed_basis");
  if (m.Has("mass_rate_basis"))
    eo.mass_rate_basis = eb_lr::ParseBasis(m.Text("mass_rate_basis"), "mass_rate_basis");
  eo.steady.min_window_s = m.Number("min_window_s");
}

// Whether `data` is already what eb-lr fits: one record on a uniform grid with every channel on
// every row (a simulated record), and no resampling or delay asked for.
bool FitsAsItIs(const Dataset& data, const IdentifyRequest& o,
                const std::vector<std::string>& channels) {
  if (o.preprocess.rate_hz > 0 || o.preprocess.delay_s != 0 || o.preprocess.estimate_delay ||
      data.rows() < 20)
    return false;
  for (const std::string& name : channels) {
    const Channel* c = data.Find(name);
    if (c == nullptr || !c->FullySampled() || !c->values().allFinite()) return false;
  }
  const Eigen::VectorXd& t = data.t();
  const double dt = (t(t.size() - 1) - t(0)) / static_cast<double>(t.size() - 1);
  for (Eigen::Index k = 1; k < t.size(); ++k)
    if (std::abs(t(k) - t(k - 1) - dt) > 1e-3 * dt) return false;
  return true;
}

// Each sampled row's time and value of a channel, finite ones only.
struct Samples {
  std::vector<double> t, y;
};
Samples SamplesOf(const Dataset& data, const std::string& name) {
  const Channel* c = data.Find(name);
  if (c == nullptr) throw InputError("eb-lr: the data have no channel '" + name + "'");
  Samples s;
  c->ForEachSample([&](Eigen::Index row, double value) {
    if (!std::isfinite(value)) return;
    s.t.push_back(data.t()(row));
    s.y.push_back(value);
  });
  if (s.t.size() < 2) throw InputError("eb-lr: channel '" + name + "' has fewer than 2 samples");
  return s;
}

double MedianStep(const std::vector<double>& t) {
  std::vector<double> d(t.size() - 1);
  for (size_t k = 0; k + 1 < t.size(); ++k) d[k] = t[k + 1] - t[k];
  std::ranges::nth_element(d, d.begin() + static_cast<std::ptrdiff_t>(d.size() / 2));
  return d[d.size() / 2];
}

// The record eb-lr fits, on a uniform grid as every method resamples one: at the request's rate,
// else the rate of the slowest channel used (a 5 Hz speed is not made 50 Hz), each grid point
// taking each channel's nearest sample (within half a step): nearest, not interpolated, so that
// white noise stays white and eb-lr's own noise estimate holds (linear interpolation of a
// jittered log underestimated it and left 2 of 15 steady windows), and a held input stays held.
// Rows without every channel are dropped; the stretches between gaps and joined records are kept
// apart. A delay asked for is the preprocessing's (preprocessing/pipeline.h, linear).
Dataset EbLrGrid(const Dataset& data, const IdentifyRequest& o,
                 const std::vector<std::string>& states, const std::vector<std::string>& inputs,
                 std::vector<Stretch>& stretches, const Logger& log) {
  std::vector<std::string> channels = states;
  channels.insert(channels.end(), inputs.begin(), inputs.end());
  if (FitsAsItIs(data, o, channels)) {
    stretches = {Stretch{0, data.rows()}};
    return data;
  }
  if (o.preprocess.delay_s != 0 || o.preprocess.estimate_delay) {
    PreprocessOptions pre = o.preprocess;
    pre.interpolation = Interpolation::kLinear;
    pre.step_breaks = false;
    pre.forces.clear();  // already derived by the caller
    const PreparedData prepared = Preprocess(data, states, inputs, pre);
    for (const std::string& note : prepared.notes) Log(log, "eb-lr: " + note);
    Dataset grid(prepared.data.t());
    for (const std::string& s : states) grid.Set(s, prepared.data[s + "_raw"]);
    for (const std::string& u : inputs) grid.Set(u, prepared.data[u]);
    stretches = Stretches(grid.t(), kGridGapFactor);
    return grid;
  }
  std::vector<Samples> samples;
  double dt = o.preprocess.rate_hz > 0 ? 1.0 / o.preprocess.rate_hz : 0.0;
  for (const std::string& name : channels) {
    samples.push_back(SamplesOf(data, name));
    if (o.preprocess.rate_hz <= 0) dt = std::max(dt, MedianStep(samples.back().t));
  }
  double first = -INFINITY, last = INFINITY;
  for (const Samples& s : samples) {
    first = std::max(first, s.t.front());
    last = std::min(last, s.t.back());
  }
  if (!(last > first)) throw InputError("eb-lr: the channels used share no time span");
  const auto n = static_cast<Eigen::Index>(std::floor((last - first) / dt + 1e-9)) + 1;
  std::vector<Eigen::VectorXd> values(channels.size(), Eigen::VectorXd(n));
  std::vector<bool> keep(static_cast<size_t>(n), true);
  for (size_t c = 0; c < channels.size(); ++c) {
    const Samples& s = samples[c];
    size_t j = 0;
    for (Eigen::Index k = 0; k < n; ++k) {
      const double g = first + static_cast<double>(k) * dt;
      while (j + 1 < s.t.size() && std::abs(s.t[j + 1] - g) <= std::abs(s.t[j] - g)) ++j;
      values[c](k) = s.y[j];
      if (std::abs(s.t[j] - g) > 0.5 * dt * (1 + 1e-6)) keep[static_cast<size_t>(k)] = false;
    }
  }
  Eigen::VectorXd t(n);
  for (Eigen::Index k = 0; k < n; ++k) t(k) = first + static_cast<double>(k) * dt;
  Dataset grid(t);
  for (size_t c = 0; c < channels.size(); ++c) grid.Set(channels[c], values[c]);
  const long dropped = std::ranges::count(keep, false);
  if (dropped > 0) grid.KeepRows(keep);
  stretches = Stretches(grid.t(), kGridGapFactor);
  std::ostringstream rate;
  rate << std::setprecision(4) << 1.0 / dt;
  Log(log, "eb-lr: resampled to " + rate.str() + " Hz (nearest sample), " +
               std::to_string(grid.rows()) + " rows" +
               (dropped > 0 ? ", " + std::to_string(dropped) + " without every channel dropped"
                            : std::string()) +
               (stretches.size() > 1 ? ", " + std::to_string(stretches.size()) + " stretches"
                                     : std::string()));
  return grid;
}

nlohmann::json IdentifyEbLrModel(const Dataset& data, const IdentifyRequest& o,
                                 const MethodOptions& options, const Logger& log) {
  ChannelFit fit = PrepareChannelFit(data, o, EbLrChannels(o), log);
  const std::vector<std::string>& states = fit.channels.states;
  const std::vector<std::string>& inputs = fit.channels.inputs;
  eb_lr::EbLrOptions eo = EbLrOptionsFor(o, inputs, data);
  ReadOptions(options, eo);
  std::vector<std::string> used = inputs;
  if (!eo.thrust_loss_channel.empty()) used.push_back(eo.thrust_loss_channel);
  for (const std::string& h : eo.held_inputs) used.push_back(h);
  std::ranges::sort(used);
  used.erase(std::unique(used.begin(), used.end()), used.end());
  std::vector<Stretch> stretches;
  const Dataset grid = EbLrGrid(data, o, states, used, stretches, log);
  const eb_lr::EbLrIdentification id =
      eb_lr::IdentifyWithEbLr(grid, stretches, states[0], states[1], inputs[0], inputs[1], eo);
  for (const auto& w : id.details.at("warnings")) Log(log, "eb-lr: " + w.get<std::string>());
  fit.model["parameters"] = id.parameters;
  fit.model["equations"] = id.equations;
  fit.model["eb_lr"] = id.details;
  if (!eo.thrust_loss_channel.empty() &&
      std::ranges::find(inputs, eo.thrust_loss_channel) == inputs.end())
    fit.model["inputs"].push_back(eo.thrust_loss_channel);
  SetTrain(fit, o);
  return fit.model;
}

}  // namespace

Method EbLrMethod() {
  Method m;
  m.name = std::string(eb_lr::kMethodName);
  m.summary = "Eriksen-Breivik 2-DOF regression on step-grid data";
  const eb_lr::EbLrOptions d;
  m.options = {
      ChoiceOption("order", "auto", {"auto", "full"},
                   "auto: with too few steady windows, sigma on the terms they excite and "
                   "separate (a warning in model.json), an equation they excite none of on its "
                   "first term, fitted with the mass from the transients; full: refuse such a "
                   "record"),
      FlagOption("constant_thrust",
                 "fit a record whose thrust is held at one level (a zig-zag, a turning circle): "
                 "sigma_U then holds at the speeds that level reaches"),
      TextOption("sigma_speed_basis", std::nullopt,
                 "sigma_U's terms, e.g. U,U^2,U^3,r^2 (factors 1, U, r, abs(r), powers ^n); "
                 "none: " +
                     eb_lr::BasisText(d.sigma_speed_basis) +
                     ", on the jets' forces U,1,U^2,U^3,U^4,r^2,r^4 and the thrust's loss "
                     "jet_flow*U"),
      TextOption("sigma_rate_basis", std::nullopt,
                 "sigma_r's terms; none: " + eb_lr::BasisText(d.sigma_rate_basis)),
      TextOption("mass_speed_basis", std::nullopt,
                 "m_U's terms; none: " + eb_lr::BasisText(d.mass_speed_basis)),
      TextOption(
          "mass_rate_basis", std::nullopt,
          "m_r's terms; none: " + eb_lr::BasisText(d.mass_rate_basis) + ", on the jets' forces 1"),
      NumberOption("min_window_s", d.steady.min_window_s, 0, kUnbounded,
                   "shortest steady window [s]: the last settled stretch of a held step at least "
                   "this long",
                   true),
  };
  m.identify = IdentifyEbLrModel;
  m.channel_inputs = true;
  return m;
}

}  // namespace usvid
