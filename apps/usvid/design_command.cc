// usvid design --vessel V --method refit|fossen-ceres --maneuvers M1,M2,... [--noise S]
//              [--duration T] [--optimize] [--check N] [--threads N] --out DIR
// Which sea trial to run, before running it: each maneuver's Fisher information for the
// method's parameters (design/information.h), their predicted standard deviations, log det,
// condition number and weakest directions; with --optimize, each family's knobs searched for the
// largest log det (design/optimize.h); with --check, N seeded fits of each maneuver beside the
// prediction (design/spread_check.h). Writes DIR/design.json and DIR/design.svg.

#include <algorithm>
#include <iostream>
#include <memory>

#include "apps/usvid/commands.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "design/design_report.h"
#include "design/information.h"
#include "design/optimize.h"
#include "design/spread_check.h"
#include "simulation/vessel_simulator.h"

namespace usvid {
namespace {

struct DesignOptions {
  std::string vessel, method, out;
  std::vector<std::string> maneuvers;
  double noise = 0.005, duration = 600.0;
  int check = 0, threads = 1;
  bool optimize = false;
};

void RunDesign(const DesignOptions& o) {
  design::MethodProblem(o.vessel, o.method);  // a bad vessel or method before any work
  if (o.check == 1) throw InputError("--check: at least 2 runs to measure a spread");
  design::DesignStudy study;
  study.vessel = o.vessel;
  study.method = o.method;
  study.noise = o.noise;
  study.duration_s = o.duration;
  // The sensors' noise, the same for every maneuver: a fraction of each state's spread on the
  // first maneuver.
  const design::NoiseModel noise = design::ReferenceNoise(
      design::SimulateManeuver(o.vessel, o.maneuvers.at(0), o.duration, 1),
      FindVessel(o.vessel).Info().states, o.noise);
  for (const std::string& m : o.maneuvers) {
    study.maneuvers.push_back(design::InformationOf(o.vessel, o.method, m, o.duration, noise));
    std::cerr << "usvid design: " << m << ": log det " << study.maneuvers.back().log_det
              << ", condition " << study.maneuvers.back().condition_number << '\n';
  }
  if (o.optimize) {
    std::vector<std::string> families;
    for (const std::string& m : o.maneuvers) {
      const std::string family = m.substr(0, m.find(':'));
      if (std::find(families.begin(), families.end(), family) != families.end()) continue;
      families.push_back(family);
      auto best = design::OptimizeManeuver(o.vessel, o.method, family, o.duration, noise);
      if (!best) {
        std::cerr << "usvid design: " << family << " has no knob to optimise\n";
        continue;
      }
      best->optimized_from = family;
      std::cerr << "usvid design: optimised " << family << ": " << best->maneuver << ", log det "
                << best->log_det << '\n';
      study.maneuvers.push_back(std::move(*best));
    }
  }
  for (const design::ManeuverInformation& m : study.maneuvers) {
    if (o.check == 0) {
      study.checks.emplace_back();
      continue;
    }
    study.checks.push_back(
        design::CheckSpread(o.vessel, o.method, m, o.duration, noise, o.check, o.threads));
    std::cerr << "usvid design: " << m.maneuver << ": checked by " << o.check
              << " fits, median predicted/observed sd " << study.checks.back()->median_ratio
              << '\n';
  }
  EnsureOutputDirectory(o.out);
  WriteFileAtomically(o.out + "/design.json", design::DesignJson(study).dump(2) + "\n");
  design::WriteDesignFigure(study, o.out + "/design.svg");
  std::cerr << "usvid design: best " << study.maneuvers[design::Best(study)].maneuver << "; wrote "
            << o.out << "/design.json, design.svg\n";
}

}  // namespace

void AddDesignCommand(CLI::App& app) {
  auto o = std::make_shared<DesignOptions>();
  CLI::App* cmd = app.add_subcommand(
      "design", "Which maneuver to run for a method: Fisher information through the simulator");
  cmd->add_option("--vessel", o->vessel, "Simulator whose trials are designed")->required();
  cmd->add_option("--method", o->method,
                  "refit (the vessel's own coefficients) or fossen-ceres (odin3dof)")
      ->required();
  cmd->add_option("--maneuvers", o->maneuvers,
                  "Maneuvers to compare, as `usvid simulate --maneuver` takes them")
      ->required()
      ->delimiter(',');
  cmd->add_option("--noise", o->noise,
                  "Measurement noise, a fraction of each channel's standard deviation on the "
                  "first maneuver (the same sensors for every maneuver)")
      ->capture_default_str();
  cmd->add_option("--duration", o->duration, "Trial length [s]")->capture_default_str();
  cmd->add_option("--check", o->check,
                  "Fit N seeded noisy runs of each maneuver and put their spread beside the "
                  "prediction")
      ->check(CLI::NonNegativeNumber);
  cmd->add_flag("--optimize", o->optimize,
                "Search each maneuver family's knobs (zig-zag angles, step hold time, PRBS clock, "
                "multisine band) for the largest log det, with NLopt");
  cmd->add_option("--threads", o->threads, "Fits run in parallel")->check(CLI::PositiveNumber);
  cmd->add_option("--out", o->out, "Directory for design.json and design.svg")->required();
  cmd->callback([o] { RunDesign(*o); });
}

}  // namespace usvid
