// usvid vessel --vessel V [--params P.json] [--points N] --out DIR
// Characterises a simulator: its channels and parameters, the steady speed for each thrust
// command, the steady turn at full yaw, and (where the model has them) resistance and Froude
// number against speed with the displacement / semi-displacement / planing bands. Writes
// DIR/vessel.json and SVG plots, and prints the steady-state table.

#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>

#include "apps/usvid/commands.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/json_file.h"
#include "plot/svg_plot.h"
#include "simulation/characterisation.h"

namespace usvid {
namespace {

struct VesselOptions {
  std::string vessel;
  std::string params;
  int points = 21;
  std::string out;
};

constexpr double kDisplacementFn = 0.4, kPlaningFn = 1.1;

std::string FormatFixed(double v, int decimals) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

// Speed at a Froude number, by bisection on the vessel's own FroudeNumber (monotonic in speed).
double SpeedAtFroude(const VesselSimulator& sim, double fn) {
  double lo = 0.0, hi = 100.0;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (*sim.FroudeNumber(mid) < fn ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

void AddRegimeBands(LinePlot& plot, const VesselSimulator& sim) {
  const double u1 = SpeedAtFroude(sim, kDisplacementFn), u2 = SpeedAtFroude(sim, kPlaningFn);
  plot.AddBand(-INFINITY, u1, "displacement (Fn < 0.4)");
  plot.AddBand(u1, u2, "semi-displacement");
  plot.AddBand(u2, INFINITY, "planing (Fn > 1.1)");
}

// The steady states at `o.points` thrust commands, straight and at full yaw: printed as a table,
// added to `report` and drawn (steady_speed.svg, turning_radius.svg).
void SteadyStates(const VesselOptions& o, const VesselSimulator& sim,
                  const std::vector<double>& params, nlohmann::json& report) {
  const VesselInfo& info = sim.Info();
  const Actuation& act = info.actuation;
  std::cerr << "usvid vessel: steady states of " << info.name << " at " << o.points
            << " thrust commands, straight and at full yaw\n";
  const auto straight = SteadySweep(sim, params, o.points, 0.0);
  const auto turning = SteadySweep(sim, params, o.points, act.yaw_full);
  Eigen::VectorXd thrust(o.points), speed(o.points), turn_speed(o.points), radius(o.points);
  std::printf("%12s %12s %8s %18s %14s %12s\n", info.inputs[act.thrust_input].c_str(),
              "speed [m/s]", "Fn", "regime", "turn U [m/s]", "radius [m]");
  for (int k = 0; k < o.points; ++k) {
    thrust(k) = straight[k].thrust;
    speed(k) = straight[k].speed;
    turn_speed(k) = turning[k].speed;
    radius(k) = turning[k].radius;
    nlohmann::json row = {{"thrust", thrust(k)},
                          {"speed", speed(k)},
                          {"settled", straight[k].settled},
                          {"turn_speed", turn_speed(k)},
                          {"turn_rate", turning[k].rate},
                          {"turn_radius_m", radius(k)}};
    std::string regime = "";
    if (const auto fn = sim.FroudeNumber(speed(k))) {
      regime = *fn < kDisplacementFn ? "displacement"
               : *fn > kPlaningFn    ? "planing"
                                     : "semi-displacement";
      row["froude"] = *fn;
      row["regime"] = regime;
    }
    report["steady"].push_back(row);
    const auto fn = sim.FroudeNumber(speed(k));
    const std::string fn_text = fn ? FormatFixed(*fn, 3) : "-";  // no length: no Froude number
    std::printf("%12.4g %12.3f %8s %18s %14.3f %12.1f\n", thrust(k), speed(k), fn_text.c_str(),
                regime.c_str(), turn_speed(k), radius(k));
  }
  const std::string thrust_name = info.inputs[act.thrust_input];
  LinePlot steady;
  steady.SetTitle(info.name + ": steady speed, straight and in a full-yaw turn")
      .SetXLabel(thrust_name)
      .SetYLabel("speed", "m/s")
      .AddSeries("straight", thrust, speed)
      .AddSeries("full-yaw turn", thrust, turn_speed);
  steady.WriteSvg(o.out + "/steady_speed.svg", 900, 500);
  LinePlot turn;
  turn.SetTitle(info.name + ": steady turning radius at full yaw")
      .SetXLabel(thrust_name)
      .SetYLabel("radius", "m")
      .AddSeries("U / |r|", thrust, radius);
  turn.WriteSvg(o.out + "/turning_radius.svg", 900, 500);
}

// The calm-water resistance and the Froude number over 0.05-20 m/s: added to `report` and drawn
// with the regimes' bands (resistance.svg, froude.svg).
void ResistanceCurve(const VesselOptions& o, const VesselSimulator& sim,
                     const std::vector<double>& params, nlohmann::json& report) {
  const std::string& name = sim.Info().name;
  const int n = 200;
  Eigen::VectorXd u = Eigen::VectorXd::LinSpaced(n, 0.05, 20.0), r(n), fn(n);
  for (int k = 0; k < n; ++k) {
    r(k) = *sim.Resistance(u(k), params);
    fn(k) = *sim.FroudeNumber(u(k));
    report["resistance"].push_back({{"speed", u(k)}, {"resistance_n", r(k)}, {"froude", fn(k)}});
  }
  LinePlot resistance;
  resistance.SetTitle(name + ": calm-water resistance")
      .SetXLabel("speed", "m/s")
      .SetYLabel("resistance", "N")
      .AddSeries("R(U)", u, r);
  AddRegimeBands(resistance, sim);
  resistance.WriteSvg(o.out + "/resistance.svg", 900, 500);
  LinePlot froude;
  froude.SetTitle(name + ": Froude number U / sqrt(g L)")
      .SetXLabel("speed", "m/s")
      .SetYLabel("Fn")
      .AddSeries("Fn", u, fn);
  AddRegimeBands(froude, sim);
  froude.WriteSvg(o.out + "/froude.svg", 900, 500);
}

void RunVessel(const VesselOptions& o) {
  if (o.points < 2 || o.points > 201) throw InputError("--points: must be in [2, 201]");
  const VesselSimulator& sim = FindVessel(o.vessel);
  const VesselInfo& info = sim.Info();
  std::vector<double> params = info.default_params;
  if (!o.params.empty()) params = info.ParamsFromFile(o.params);
  EnsureOutputDirectory(o.out);
  nlohmann::json report = {{"vessel", info.name},
                           {"states", info.states},
                           {"derived", info.derived},
                           {"inputs", info.inputs},
                           {"transport_delay_s", info.transport_delay_s}};
  for (size_t i = 0; i < params.size(); ++i) report["parameters"][info.params[i]] = params[i];
  if (!info.estimated.empty()) {
    report["estimated"] = info.estimated;
    std::printf("estimated from the particulars (docs/model.md#estimates-from-the-particulars):\n");
    for (const std::string& e : info.estimated) std::printf("  %s\n", e.c_str());
  }
  if (info.actuation.thrust_input >= 0 && info.actuation.speed_state >= 0)
    SteadyStates(o, sim, params, report);
  if (sim.Resistance(1.0, params) && sim.FroudeNumber(1.0)) ResistanceCurve(o, sim, params, report);
  WriteJsonFile(o.out + "/vessel.json", report);
  std::cerr << "usvid vessel: wrote " << o.out << "/vessel.json and plots\n";
}

}  // namespace

void AddVesselCommand(CLI::App& app) {
  auto o = std::make_shared<VesselOptions>();
  CLI::App* cmd = app.add_subcommand(
      "vessel", "Characterise a simulator: parameters, steady speed and turning, resistance");
  cmd->add_option("--vessel", o->vessel, "The simulator: " + VesselChoices())->required();
  cmd->add_option("--params", o->params, "JSON of parameter overrides (name: value)");
  cmd->add_option("--points", o->points, "Thrust commands in the steady-state sweep");
  cmd->add_option("--out", o->out, "Directory for vessel.json and the plots")->required();
  cmd->callback([o] { RunVessel(*o); });
}

}  // namespace usvid
