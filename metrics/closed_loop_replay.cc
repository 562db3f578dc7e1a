#include "metrics/closed_loop_replay.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <memory>
#include <numbers>
#include <optional>
#include <sstream>

#include "core/derived_channels.h"
#include "core/error.h"
#include "core/model_view.h"
#include "maneuvers/maneuver_factory.h"
#include "maneuvers/maneuver_spec.h"
#include "maneuvers/true_wind.h"
#include "metrics/equation_model.h"
#include "metrics/free_run.h"
#include "metrics/maneuver_of_record.h"
#include "metrics/rank_tests.h"
#include "metrics/recorded_yaw_rate.h"
#include "metrics/turning_response.h"
#include "metrics/wind_aboard.h"
#include "metrics/zigzag_response.h"
#include "preprocessing/actuator_dynamics.h"
#include "preprocessing/waterjet_forces.h"
#include "simulation/input_track.h"
#include "simulation/recorded_inputs.h"
#include "simulation/vessel_simulator.h"

namespace usvid {
namespace {

constexpr double kMaxStep = 0.01;  // [s] integration step, as the free run's

bool Varies(const Eigen::VectorXd& v) {
  for (Eigen::Index k = 1; k < v.size(); ++k)
    if (std::isfinite(v(k)) && std::isfinite(v(0)) && v(k) != v(0)) return true;
  return false;
}

// The median of a channel's samples (unsampled ones left out).
double SampledMedian(const Eigen::VectorXd& v) {
  std::vector<double> x;
  for (double value : v)
    if (std::isfinite(value)) x.push_back(value);
  return x.empty() ? 0.0 : Median(std::move(x));
}

// A recorded channel's samples as a zero-order-hold track in the record's time.
InputTrack RecordedTrack(const Dataset& recorded, const std::string& name) {
  InputTrack track(1);
  recorded.Get(name).ForEachSample(
      [&](Eigen::Index k, double v) { track.Append(recorded.t()(k), std::span(&v, 1)); });
  return track;
}

// The input index of the command `name`, or -1.
int CommandIndex(const Actuation& act, const std::string& name) {
  const auto it = std::ranges::find(act.input_names, name);
  return it == act.input_names.end() ? -1 : static_cast<int>(it - act.input_names.begin());
}

// The air over the ground on the record's rows [north, east] as a zero-order-hold track in the
// record's time.
InputTrack AirTrack(const Dataset& recorded, const Eigen::VectorXd& north,
                    const Eigen::VectorXd& east) {
  InputTrack track(2);
  for (Eigen::Index k = 0; k < recorded.rows(); ++k)
    track.Append(recorded.t()(k), std::array<double, 2>{north(k), east(k)});
  return track;
}

// The maneuver, with every command but the yaw held at the record's first value: the record's
// approach (its thrust, its bucket), which a vessel's default cruise need not be. A measured
// disturbance (the wind) follows the record in time instead, zero-order hold. The relative wind
// of a record that logs the heading and velocities is the true wind seen from the record's hull:
// the replay takes the true wind from it (the air's velocity over the ground, turned by the
// difference between the replay's first heading and the record's) and gives the model the
// relative wind its own heading and velocities make of it. Read as recorded, the wind would turn
// with the record's heading, not the model's: over a turning circle the two part by up to a radian.
class RecordedApproach : public Maneuver {
 public:
  RecordedApproach(std::unique_ptr<Maneuver> inner, const Actuation& act, const Dataset& recorded)
      : inner_(std::move(inner)),
        act_(act),
        held_(act.inputs(), NAN),
        followed_(act.inputs(), InputTrack(1)) {
    for (int i = 0; i < act.inputs(); ++i) {
      if (i == act.yaw_input || !recorded.Has(act.input_names[i])) continue;
      if (act.roles[i] != InputRole::kMeasured) {
        held_[i] = recorded[act.input_names[i]](0);
        continue;
      }
      followed_[i] = RecordedTrack(recorded, act.input_names[i]);
    }
    FollowTrueWind(recorded);
  }
  std::string Spec() const override { return inner_->Spec(); }
  double Duration() const override { return inner_->Duration(); }
  std::vector<double> InitialCommand() const override {
    std::vector<double> u = inner_->InitialCommand();
    Hold(0.0, u);
    return u;
  }
  void Command(double t, std::span<const double> state, std::span<double> u) override {
    inner_->Command(t, state, u);
    Hold(t, u);
    if (air_.size() == 0) return;
    if (!std::isfinite(turn_)) turn_ = state[act_.heading_state] - recorded_psi0_;
    const double* air = air_.At(t + 1e-12);
    const std::array<double, 2> rel =
        RelativeWindOf({air[0], air[1]}, state[act_.heading_state] - turn_, state[act_.speed_state],
                       state[act_.speed_state + 1]);
    u[wind_speed_] = rel[0];
    u[wind_direction_] = rel[1];
  }
  bool Done() const override { return inner_->Done(); }
  nlohmann::json Report() const override { return inner_->Report(); }
  std::unique_ptr<Maneuver> Clone() const override {
    return std::make_unique<RecordedApproach>(*this);
  }

 private:
  template <typename U>
  void Hold(double t, U& u) const {
    for (size_t i = 0; i < held_.size(); ++i) {
      if (std::isfinite(held_[i])) u[i] = held_[i];
      if (followed_[i].size() > 0) u[i] = followed_[i].At(t + 1e-12)[0];
    }
  }
  // The air over the ground on the record's rows (RecordedAirOverGround), when the vessel reads
  // the wind and has a heading and surge-sway states.
  void FollowTrueWind(const Dataset& recorded) {
    wind_speed_ = CommandIndex(act_, "wind_speed");
    wind_direction_ = CommandIndex(act_, "wind_direction");
    if (wind_speed_ < 0 || wind_direction_ < 0 || act_.roles[wind_speed_] != InputRole::kMeasured ||
        act_.roles[wind_direction_] != InputRole::kMeasured || act_.heading_state < 0 ||
        act_.speed_state < 0 || !act_.speed_is_surge)
      return;
    const std::optional<std::array<Eigen::VectorXd, 2>> air = RecordedAirOverGround(recorded);
    if (!air) return;
    const Eigen::VectorXd& psi = recorded["psi"];
    for (Eigen::Index k = 0; k < psi.size() && !std::isfinite(recorded_psi0_); ++k)
      recorded_psi0_ = psi(k);
    air_ = AirTrack(recorded, (*air)[0], (*air)[1]);
  }
  InnerManeuver inner_;
  Actuation act_;
  std::vector<double> held_;
  std::vector<InputTrack> followed_;  // per measured input, its record (one value each); else empty
  InputTrack air_{2};  // the true wind over the ground [north, east], in the record's frame
  double recorded_psi0_ = NAN;  // the record's first heading
  double turn_ = NAN;           // the replay's first heading less the record's
  int wind_speed_ = -1, wind_direction_ = -1;
};

double SampleRate(const Dataset& d) {
  if (d.rows() < 2) throw InputError(d.SourcePrefix() + "closed loop: fewer than two rows");
  return (d.rows() - 1) / d.duration();
}

// The commands issued so far, for the input in force at a (delayed) time.
class CommandHistory {
 public:
  explicit CommandHistory(std::vector<double> initial) : initial_(std::move(initial)) {}
  void Append(double t, const std::vector<double>& u) {
    times_.push_back(t);
    commands_.push_back(u);
  }
  double At(double t, int input) const {
    const auto it = std::upper_bound(times_.begin(), times_.end(), t + 1e-12);
    if (it == times_.begin()) return initial_[input];
    return commands_[it - times_.begin() - 1][input];
  }

 private:
  std::vector<double> initial_;
  std::vector<double> times_;
  std::vector<std::vector<double>> commands_;
};

// An actuator state the model reads: simulated from its command, or held.
struct ActuatorState {
  std::string channel;
  int command = -1;                    // the command's input index
  std::optional<ActuatorModel> model;  // none: held at `value`
  double value = 0.0;
};

ClosedLoopReplay ReplayVesselModel(const nlohmann::json& model, Maneuver& maneuver, double rate_hz,
                                   const Dataset& recorded, bool from_recorded_state) {
  const VesselModel vessel = ParseVesselModel(model);
  RunOptions options;
  options.rate_hz = rate_hz;
  if (from_recorded_state) {
    // The record's first row, for the states it has (positions and heading start at 0).
    const VesselInfo& info = vessel.simulator->Info();
    options.initial_state.assign(info.states.size(), NAN);
    for (size_t i = 0; i < info.states.size(); ++i)
      if (!IsPositionOrHeading(info.states[i]) && recorded.Has(info.states[i]) &&
          std::isfinite(recorded[info.states[i]](0)))
        options.initial_state[i] = recorded[info.states[i]](0);
  }
  const SimulationResult r = vessel.simulator->RunManeuver(
      maneuver, vessel.params,
      ValuesOf(vessel.effects, vessel.simulator->Info().inputs, vessel.simulator->Info().states),
      options);
  ClosedLoopReplay out;
  out.run = r.data;
  out.diverged = r.diverged;
  out.diverged_at_s = r.diverged_at_s;
  if (r.diverged) out.diverged_channel = "(simulator)";
  return out;
}

// Each input's source: a command, an actuator state, or a jet force from the actuator states.
enum class SourceKind { kCommand, kActuator, kForce, kRecorded };

// Where each of an equation model's inputs comes from (the index of its command, actuator
// state, jet force or recorded disturbance), and the actuator states the inputs need.
struct InputSources {
  std::vector<std::pair<SourceKind, int>> sources;
  std::vector<ActuatorState> actuators;
  std::vector<InputTrack> recorded;       // per recorded disturbance, its samples (one value each)
  std::array<int, 3> jet = {-1, -1, -1};  // the jet states among the actuators (-1: none)
  bool any_force = false;
  // A logged wind the model reads, met on its own heading (metrics/wind_aboard.h): the air over
  // the ground, zero-order hold; engaged only for a model that integrates psi, u and v.
  std::optional<WindAboard> wind;
  InputTrack air{2};
};

// The model's states (x, in its channels' order) and the actuator states (y).
struct ReplayState {
  Eigen::VectorXd x;
  std::vector<double> y;
};

// The replay's time grid: the record's sample period, split into integration steps of at most
// kMaxStep, over the record's duration.
struct ReplayClock {
  double period = 0.0;
  int substeps = 1;
  double h = 0.0;  // the integration step
  long ticks = 0;  // samples
};

ReplayClock ClockFor(const Dataset& recorded) {
  ReplayClock c;
  c.period = 1.0 / SampleRate(recorded);
  c.substeps = std::max(1, static_cast<int>(std::ceil(c.period / kMaxStep - 1e-9)));
  c.h = c.period / c.substeps;
  c.ticks = static_cast<long>(std::floor(recorded.duration() / c.period + 1e-9)) + 1;
  return c;
}

// Whether the model's inputs include jet forces computed from the actuator states.
bool JetForces(const nlohmann::json& model) { return ModelView(model).Forces() == "waterjet"; }

// The index of actuator state `state` among `actuators`, added when new: simulated from its
// command when the record's command varies, else held at the record's median. Throws
// InputError when the record lacks the state or its command.
int ActuatorIndex(const std::string& state, const Actuation& act, const Dataset& recorded,
                  std::vector<ActuatorState>& actuators) {
  for (size_t i = 0; i < actuators.size(); ++i)
    if (actuators[i].channel == state) return static_cast<int>(i);
  ActuatorState a;
  a.channel = state;
  for (const auto& [command, s] : kWaterjetActuators)
    if (s == state) a.command = CommandIndex(act, command);
  if (a.command < 0 || !recorded.Has(state) || !recorded.Has(act.input_names[a.command]))
    throw InputError("the record lacks '" + state + "' or its command");
  if (Varies(recorded[act.input_names[a.command]])) {
    a.model = IdentifyActuator(recorded, act.input_names[a.command], state);
  } else {
    a.value = SampledMedian(recorded[state]);
  }
  actuators.push_back(a);
  return static_cast<int>(actuators.size() - 1);
}

// The source of each of the model's inputs. Throws InputError for an input that is neither a
// command of the vessel, nor derived from one, nor a disturbance the record logs.
InputSources ResolveInputs(const EquationModel& system, const VesselInfo& info, bool jet_forces,
                           const Dataset& recorded) {
  const Actuation& act = info.actuation;
  InputSources in;
  for (const std::string& name : system.Inputs()) {
    if (const int c = CommandIndex(act, name); c >= 0) {
      in.sources.push_back({SourceKind::kCommand, c});
    } else if (std::ranges::find(kWaterjetStateChannels, name) != kWaterjetStateChannels.end()) {
      in.sources.push_back(
          {SourceKind::kActuator, ActuatorIndex(name, act, recorded, in.actuators)});
    } else if (const auto f = std::ranges::find(kWaterjetForceChannels, name);
               jet_forces && f != kWaterjetForceChannels.end()) {
      for (const std::string& s : kWaterjetStateChannels)
        ActuatorIndex(s, act, recorded, in.actuators);
      in.sources.push_back(
          {SourceKind::kForce, static_cast<int>(f - kWaterjetForceChannels.begin())});
    } else if (info.StateIndex(name) < 0 &&
               std::ranges::find(info.derived, name) == info.derived.end() && recorded.Has(name) &&
               recorded.Get(name).SampleCount() > 0) {
      // A disturbance the record logs (the wind, the current: a measured track's inputs)
      // follows the record in time, zero-order hold, as a vessel's measured inputs do
      // (RecordedApproach).
      in.recorded.push_back(RecordedTrack(recorded, name));
      in.sources.push_back({SourceKind::kRecorded, static_cast<int>(in.recorded.size() - 1)});
    } else {
      throw InputError("input '" + name + "' is neither a command of " + info.name +
                       ", nor derived from one, nor a disturbance the record logs");
    }
  }
  // Where the jet states sit among the actuators, for the forces (-1: no force input).
  for (size_t j = 0; j < in.jet.size(); ++j)
    for (size_t a = 0; a < in.actuators.size(); ++a)
      if (in.actuators[a].channel == kWaterjetStateChannels[j]) in.jet[j] = static_cast<int>(a);
  in.any_force =
      std::ranges::any_of(in.sources, [](const auto& s) { return s.first == SourceKind::kForce; });
  WindAboard wind(recorded, system.Inputs(), system.Channels());
  if (wind.engaged() && wind.u_channel() >= 0 && wind.v_channel() >= 0) {
    in.air = AirTrack(recorded, wind.air_north(), wind.air_east());
    in.wind = std::move(wind);
  }
  return in;
}

// The record's first row: the model's states (0 where unrecorded) and the actuator states
// (a held one at its value).
ReplayState InitialState(const std::vector<std::string>& channels,
                         const std::vector<ActuatorState>& actuators, const Dataset& recorded) {
  const auto n = static_cast<Eigen::Index>(channels.size());
  ReplayState state;
  state.x.resize(n);
  for (Eigen::Index i = 0; i < n; ++i)
    state.x(i) = recorded.Has(channels[i]) ? recorded[channels[i]](0) : 0.0;
  state.y.resize(actuators.size());
  for (size_t a = 0; a < actuators.size(); ++a)
    state.y[a] = actuators[a].model ? recorded[actuators[a].channel](0) : actuators[a].value;
  return state;
}

// The state the maneuver sees, in the vessel's order: the model's, the actuators', else the
// record's first row (a state none of them has keeps its value).
void FillVesselState(const VesselInfo& info, const EquationModel& system,
                     const std::vector<ActuatorState>& actuators, const Dataset& recorded,
                     const ReplayState& state, std::vector<double>& vessel_state) {
  for (size_t i = 0; i < info.states.size(); ++i) {
    const std::string& s = info.states[i];
    if (const int c = system.Index(s); c >= 0) {
      vessel_state[i] = state.x(c);
    } else if (recorded.Has(s)) {
      vessel_state[i] = recorded[s](0);
    }
    for (size_t a = 0; a < actuators.size(); ++a)
      if (actuators[a].channel == s) vessel_state[i] = state.y[a];
  }
}

// The model and the simulated actuators integrated over one sample period from t, under the
// commands issued so far (each delayed by its own delay).
void AdvanceTick(const EquationModel& system, const InputSources& in, const CommandHistory& history,
                 const ReplayClock& clock, double t, ReplayState& state) {
  const std::vector<ActuatorState>& actuators = in.actuators;
  std::vector<double>& y = state.y;
  Eigen::VectorXd u(static_cast<Eigen::Index>(in.sources.size()));
  for (int s = 0; s < clock.substeps; ++s) {
    const double ts = t + s * clock.h;
    for (size_t a = 0; a < actuators.size(); ++a)
      if (actuators[a].model)
        y[a] = ActuatorStep(*actuators[a].model, y[a],
                            history.At(ts - actuators[a].model->delay_s, actuators[a].command),
                            clock.h);
    const std::array<double, 4> forces =
        in.any_force ? WaterjetForces(y[in.jet[0]], y[in.jet[1]], y[in.jet[2]])
                     : std::array<double, 4>{};
    for (size_t i = 0; i < in.sources.size(); ++i) {
      const auto [kind, index] = in.sources[i];
      u(static_cast<Eigen::Index>(i)) =
          kind == SourceKind::kCommand    ? history.At(ts - system.DelayS(), index)
          : kind == SourceKind::kActuator ? y[index]
          : kind == SourceKind::kForce    ? forces[index]
                                          : in.recorded[index].At(ts + 1e-12)[0];
    }
    if (in.wind) {
      const double* air = in.air.At(ts - system.DelayS() + 1e-12);
      in.wind->Set(air[0], air[1], state.x(in.wind->psi_channel()), state.x(in.wind->u_channel()),
                   state.x(in.wind->v_channel()), [&](int i, double value) { u(i) = value; });
    }
    system.Step(u, clock.h, state.x);
  }
}

// One row of the replay: the model's states, the commands, the actuator states.
std::vector<double> ReplayRow(const ReplayState& state, const std::vector<double>& command) {
  std::vector<double> row(state.x.data(), state.x.data() + state.x.size());
  row.insert(row.end(), command.begin(), command.end());
  row.insert(row.end(), state.y.begin(), state.y.end());
  return row;
}

// The replay's rows as a dataset: the model's channels, the commands and the actuator states,
// each name once (a command the model also integrates keeps the state).
Dataset ReplayDataset(const std::vector<double>& times,
                      const std::vector<std::vector<double>>& rows,
                      const std::vector<std::string>& channels, const Actuation& act,
                      const std::vector<ActuatorState>& actuators) {
  Eigen::VectorXd ts = Eigen::Map<const Eigen::VectorXd>(times.data(), times.size());
  Dataset run(ts);
  std::vector<std::string> names = channels;
  names.insert(names.end(), act.input_names.begin(), act.input_names.end());
  for (const ActuatorState& a : actuators) names.push_back(a.channel);
  for (size_t c = 0; c < names.size(); ++c) {
    if (run.Has(names[c])) continue;  // a command the model also integrates: keep the state
    Eigen::VectorXd v(static_cast<Eigen::Index>(rows.size()));
    for (size_t k = 0; k < rows.size(); ++k) v(static_cast<Eigen::Index>(k)) = rows[k][c];
    run.Set(names[c], v);
  }
  return run;
}

ClosedLoopReplay ReplayEquationModel(const nlohmann::json& model, const VesselInfo& info,
                                     Maneuver& maneuver, const Dataset& recorded) {
  const Actuation& act = info.actuation;
  const EquationModel system(model, [&](const std::string& c) { return recorded.Has(c); });
  const std::vector<std::string>& channels = system.Channels();
  const InputSources in = ResolveInputs(system, info, JetForces(model), recorded);
  const std::vector<double> initial = maneuver.InitialCommand();
  CommandHistory history(initial);
  ReplayState state = InitialState(channels, in.actuators, recorded);
  const DivergenceBounds bounds(channels, recorded);
  std::vector<double> vessel_state(info.states.size());
  const ReplayClock clock = ClockFor(recorded);
  ClosedLoopReplay out;
  std::vector<double> times;
  std::vector<std::vector<double>> rows;
  std::vector<double> command(act.inputs());
  for (long k = 0; k < clock.ticks; ++k) {
    const double t = static_cast<double>(k) * clock.period;
    FillVesselState(info, system, in.actuators, recorded, state, vessel_state);
    maneuver.Command(t, vessel_state, command);
    history.Append(t, command);
    times.push_back(t);
    rows.push_back(ReplayRow(state, command));
    if (k + 1 == clock.ticks || maneuver.Done()) break;
    AdvanceTick(system, in, history, clock, t, state);
    if (const int bad = bounds.Exceeded(state.x); bad >= 0) {
      out.diverged = true;
      out.diverged_at_s = t + clock.period;
      out.diverged_channel = channels[bad];
      break;
    }
  }
  out.run = ReplayDataset(times, rows, channels, act, in.actuators);
  return out;
}

// first_overshoot_deg -> first_overshoot_error_deg, steady_rate_deg_s -> steady_rate_error_deg_s.
std::string ErrorKey(const std::string& criterion) {
  for (const std::string unit : {"_deg_s", "_deg", "_m", "_s"})
    if (criterion.ends_with(unit))
      return criterion.substr(0, criterion.size() - unit.size()) + "_error" + unit;
  return criterion + "_error";
}

// turning[:A]: the rudder angle |A| [deg] the execute is found at; 0 (the command's largest)
// without one.
double TurningRudderDeg(const ManeuverSpec& spec) {
  return spec.numbers.empty() ? 0.0 : spec.RudderDeg();
}

// zigzag[:A/B]: the rudder angle A and the heading threshold B [deg], 20/20 by default.
ZigzagResponse AnalyseZigzag(const ManeuverSpec& spec, const Dataset& data,
                             const std::string& heading, const std::string& rudder,
                             bool replay = false) {
  return AnalyseZigzag(data, spec.CheckDeg(), heading, rudder, replay ? -1.0 : spec.RudderDeg());
}

// Throws InputError when the record's test turned the other way from `spec` (its first rudder
// order: A of zigzag:A/B or turning:A, starboard positive), saying which spec replays it: the
// replay of the mirror image would meet the wind, and the hull's and propeller's asymmetries,
// from the other side.
void CheckFirstTurn(const std::string& spec, const Dataset& recorded, const std::string& heading,
                    const std::string& rudder) {
  const ManeuverSpec parsed = ParseManeuverSpec(spec);
  const int turns = parsed.Side();
  double execute_s = 0.0;
  int recorded_turn = 0;
  if (parsed.kind == ManeuverKind::kZigzag) {
    const ZigzagResponse z = AnalyseZigzag(parsed, recorded, heading, rudder);
    recorded_turn = z.first_turn;
    execute_s = z.execute_s;
  } else {
    const TurningResponse r =
        AnalyseTurning(recorded, heading, rudder, "north", "east", true, TurningRudderDeg(parsed));
    recorded_turn = r.direction;
    execute_s = r.execute_s;
  }
  if (recorded_turn == 0 || recorded_turn == turns) return;
  std::ostringstream at;
  at << std::fixed << std::setprecision(1) << execute_s;
  throw InputError(recorded.SourcePrefix() + spec + " turns to " +
                   (turns > 0 ? "starboard" : "port") + " first, the record to " +
                   (turns > 0 ? "port" : "starboard") + " (its execute at " + at.str() +
                   " s): give " + parsed.Mirrored());
}

// A criterion's value for JSON: null when not finite.
nlohmann::json Value(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); }

}  // namespace

ClosedLoopReplay ReplayManeuver(const nlohmann::json& model, const VesselRef& vessel,
                                const std::string& spec, const Dataset& recorded,
                                bool from_recorded_state, double base_course_offset_rad) {
  const VesselInfo& info = vessel.Info();
  ManeuverSpec parsed = ParseManeuverSpec(spec);
  parsed.base_offset_rad = base_course_offset_rad;
  // An equation model's yaw command moves as the record's did (metrics/recorded_yaw_rate.h).
  const bool vessel_model = IsVesselModel(model);
  Actuation act = info.actuation;
  if (!vessel_model) act.yaw_rate_limit = ReplayYawRateLimit(act, recorded);
  std::unique_ptr<Maneuver> rule = MakeManeuver(parsed, act, recorded.duration(), 1);
  RecordedApproach maneuver(std::move(rule), act, recorded);
  if (vessel_model)
    return ReplayVesselModel(model, maneuver, SampleRate(recorded), recorded, from_recorded_state);
  return ReplayEquationModel(model, info, maneuver, recorded);
}

double ManeuverExecute(const std::string& spec, const Dataset& data, const std::string& heading,
                       const std::string& rudder) {
  const ManeuverSpec parsed = ParseManeuverSpec(spec);
  if (parsed.kind == ManeuverKind::kZigzag)
    return AnalyseZigzag(parsed, data, heading, rudder).execute_s;
  if (parsed.kind == ManeuverKind::kTurning)
    return AnalyseTurning(data, heading, rudder, "north", "east", true, TurningRudderDeg(parsed))
        .execute_s;
  throw InputError("closed loop: '" + spec + "' has no execute");
}

Dataset FromLeadIn(const std::string& spec, const Dataset& recorded, const std::string& heading,
                   const std::string& rudder) {
  const double execute = ManeuverExecute(spec, recorded, heading, rudder);
  const Eigen::VectorXd& t = recorded.t();
  const double period = 1.0 / SampleRate(recorded);
  // A steady approach of a few seconds more than the lead-in (a towing tank's) is kept.
  if (execute - t(0) <= 2.0 * kLeadInS + 1.5 * period) return recorded;
  Eigen::Index first = 0;
  while (first + 1 < recorded.rows() && t(first + 1) <= execute - kLeadInS + 1e-9) ++first;
  Dataset cut = recorded.Rows(first, recorded.rows() - first);
  cut.SetTime(cut.t().array() - cut.t()(0));
  return cut;
}

nlohmann::json ManeuverCriteria(const std::string& spec, const Dataset& data,
                                const std::string& heading, const std::string& rudder,
                                bool replay) {
  const ManeuverSpec parsed = ParseManeuverSpec(spec);
  if (parsed.kind == ManeuverKind::kZigzag) {
    const ZigzagResponse z = AnalyseZigzag(parsed, data, heading, rudder, replay);
    auto at = [](const std::vector<double>& v, size_t i) { return i < v.size() ? v[i] : NAN; };
    return {{"first_overshoot_deg", Value(at(z.overshoot_deg, 0))},
            {"second_overshoot_deg", Value(at(z.overshoot_deg, 1))},
            {"second_execute_s", Value(at(z.reversal_s, 0) - z.execute_s)},
            {"period_s", Value(at(z.reversal_s, 2) - at(z.reversal_s, 0))}};
  }
  if (parsed.kind == ManeuverKind::kTurning) {
    const TurningResponse r =
        AnalyseTurning(data, heading, rudder, "north", "east", !replay, TurningRudderDeg(parsed));
    return {{"advance_m", Value(r.advance_m)},
            {"transfer_m", Value(r.transfer_m)},
            {"tactical_diameter_m", Value(r.tactical_diameter_m)},
            {"steady_rate_deg_s", Value(r.steady_rate_deg_s)}};
  }
  throw InputError("closed loop: '" + spec + "' has no maneuver criteria");
}

std::string RecordedManeuverSpec(const std::string& spec, const VesselRef& vessel,
                                 const Dataset& recorded) {
  if (!IsBareManeuverTest(spec) || vessel.empty()) return spec;
  const Actuation& act = vessel.Info().actuation;
  // The heading as logged: a derived course needs psi itself (core/derived_channels.h).
  const std::string read = ManeuverOfRecord(recorded, spec, recorded.Has("psi") ? "psi" : "chi",
                                            act.input_names.at(act.yaw_input));
  return read.empty() ? spec : read;
}

ManeuverScorer::ManeuverScorer(const VesselRef& vessel, const std::string& spec,
                               const Dataset& recorded_data)
    : vessel_(vessel), spec_(spec) {
  Dataset full = recorded_data;
  AddDerivedChannels(full);
  const Actuation& act = vessel.Info().actuation;
  rudder_ = act.input_names.at(act.yaw_input);
  // A real log's test starts after its approach: replay from the lead-in before the execute.
  recorded_ = FromLeadIn(spec, full, full.Has("psi") ? "psi" : "chi", rudder_);
  CheckFirstTurn(spec, full, full.Has("psi") ? "psi" : "chi", rudder_);
  if (recorded_.rows() < full.rows()) replayed_from_s_ = full.t()(full.rows() - recorded_.rows());
  // A zig-zag is replayed about the base course the record's test reversed about: read once,
  // for every model scored.
  const ManeuverSpec parsed = ParseManeuverSpec(spec);
  if (parsed.kind == ManeuverKind::kZigzag) {
    try {
      base_course_offset_rad_ =
          AnalyseZigzag(parsed, recorded_, recorded_.Has("psi") ? "psi" : "chi", rudder_)
              .base_offset_deg *
          std::numbers::pi / 180.0;
    } catch (const InputError&) {
      // No zig-zag in the record to read one from: about the heading at the execute.
    }
  }
}

ClosedLoopReplay ManeuverScorer::Replay(const nlohmann::json& model) const {
  return ReplayManeuver(model, vessel_, spec_, recorded_, replayed_from_s_.has_value(),
                        base_course_offset_rad_);
}

nlohmann::json ManeuverScorer::Score(const nlohmann::json& model, ClosedLoopReplay* kept) const {
  nlohmann::json out = {{"maneuver", spec_}};
  const bool cut = replayed_from_s_.has_value();
  if (cut) out["replayed_from_s"] = *replayed_from_s_;
  ClosedLoopReplay replay;
  try {
    replay = Replay(model);
  } catch (const InputError& e) {
    out["status"] = std::string("not replayable: ") + e.what();
    return out;
  }
  // The record's criteria, read from the heading the replay has (once for each).
  const std::string heading = replay.run.Has("psi") ? "psi" : "chi";
  if (!measured_.contains(heading))
    measured_[heading] = ManeuverCriteria(spec_, recorded_, heading, rudder_);
  out["measured"] = measured_[heading];
  nlohmann::json model_criteria;
  for (const auto& [name, _] : out["measured"].items()) model_criteria[name] = nullptr;
  if (replay.diverged) {
    out["status"] = "diverged at " + std::to_string(static_cast<int>(replay.diverged_at_s)) +
                    " s (" + replay.diverged_channel + ")";
  } else {
    out["status"] = "ok";
    try {
      model_criteria = ManeuverCriteria(spec_, replay.run, heading, rudder_, true);
      bool any = false;
      for (const auto& [_, v] : model_criteria.items()) any = any || v.is_number();
      if (!any) out["status"] = "incomplete: the model never turned far enough for the criteria";
    } catch (const InputError& e) {
      out["status"] = std::string("no criteria: ") + e.what();
    }
  }
  out["model"] = model_criteria;
  for (const auto& [name, measured] : out["measured"].items()) {
    const nlohmann::json& m = model_criteria[name];
    out[ErrorKey(name)] = measured.is_number() && m.is_number()
                              ? nlohmann::json(m.get<double>() - measured.get<double>())
                              : nlohmann::json();
  }
  if (kept) *kept = std::move(replay);
  return out;
}

nlohmann::json ClosedLoopScore(const nlohmann::json& model, const VesselRef& vessel,
                               const std::string& spec, const Dataset& recorded_data,
                               ClosedLoopReplay* replay) {
  nlohmann::json out = {{"maneuver", spec}};
  if (spec.empty()) {
    out["status"] = "not replayable: recorded inputs only (the test data name no maneuver)";
    return out;
  }
  if (!IsManeuverTest(spec)) {
    out["status"] = "not replayable: " + spec + " is open-loop, scored on its recorded inputs";
    return out;
  }
  if (vessel.empty()) {
    out["status"] = "not replayable: no vessel to take the actuators and limits from";
    return out;
  }
  return ManeuverScorer(vessel, spec, recorded_data).Score(model, replay);
}

}  // namespace usvid
