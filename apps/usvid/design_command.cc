// usvid design --vessel V --method refit|fossen-ceres|eb-lr --maneuvers M1,M2,... [--noise S]
//              [--duration T] [--parameters P1,P2,...] [--optimize] [--check N] [--threads N]
//              --out DIR
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
  std::vector<std::string> maneuvers, parameters;
  double noise = 0.005, duration = 600.0;
  int check = 0, threads = 1;
  bool optimize = false;
};

void RunDesign(const DesignOptions& o) {
  design::DesignProblem problem;
  problem.vessel = o.vessel;
  problem.method = o.method;
  problem.seconds = o.duration;
  problem.focus = o.parameters;
  design::CheckProblem(problem);  // a bad vessel, method or parameter before any work
  if (o.check == 1) throw InputError("--check: at least 2 runs to measure a spread");
  // The sensors' noise, the same for every maneuver: a fraction of each state's spread on the
  // first maneuver.
  problem.noise = design::ReferenceNoise(
      design::SimulateManeuver(problem.vessel, o.maneuvers.at(0), o.duration, 1),
      problem.vessel.Info().states, o.noise);
  design::DesignStudy study;
  study.vessel = o.vessel;
  study.method = o.method;
  study.noise = o.noise;
  study.duration_s = o.duration;
  study.focus = o.parameters;
  for (const std::string& m : o.maneuvers) {
    study.maneuvers.push_back(design::InformationOf(problem, m));
    const design::ManeuverInformation& info = study.maneuvers.back();
    std::cerr << "usvid design: " << m << ": log det " << info.log_det << ", condition "
              << info.condition_number
              << (info.unusable.empty() ? "" : "; " + o.method + " cannot fit it: " + info.unusable)
              << '\n';
  }
  if (o.optimize) {
    std::vector<std::string> families;
    for (const std::string& m : o.maneuvers) {
      const std::string family = m.substr(0, m.find(':'));
      if (std::find(families.begin(), families.end(), family) != families.end()) continue;
      families.push_back(family);
      auto best = design::OptimizeManeuver(problem, family);
      if (!best) {
        std::cerr << "usvid design: " << family << " has no knob to optimise\n";
        continue;
      }
      best->optimized_from = family;
      std::cerr << "usvid design: optimised " << family << ": " << best->maneuver << ", log det "
                << best->log_det << (best->unusable.empty() ? "" : " (no usable design found)")
                << '\n';
      study.maneuvers.push_back(std::move(*best));
    }
  }
  for (const design::ManeuverInformation& m : study.maneuvers) {
    if (o.check == 0 || !m.unusable.empty()) {
      study.checks.emplace_back();
      continue;
    }
    study.checks.push_back(design::CheckSpread(problem, m, o.check, o.threads));
    std::cerr << "usvid design: " << m.maneuver << ": checked by " << o.check
              << " fits, median predicted/observed sd " << study.checks.back()->median_ratio
              << '\n';
  }
  EnsureOutputDirectory(o.out);
  WriteFileAtomically(o.out + "/design.json", design::DesignJson(study).dump(2) + "\n");
  design::WriteDesignFigure(study, o.out + "/design.svg");
  std::cerr << "usvid design: best "
            << (design::AnyUsable(study) ? study.maneuvers[design::Best(study)].maneuver
                                         : "none (" + o.method + " can fit no maneuver listed)")
            << "; wrote " << o.out << "/design.json, design.svg\n";
}

}  // namespace

void AddDesignCommand(CLI::App& app) {
  auto o = std::make_shared<DesignOptions>();
  CLI::App* cmd = app.add_subcommand(
      "design", "Which maneuver to run for a method: Fisher information through the simulator");
  cmd->add_option("--vessel", o->vessel, "Simulator whose trials are designed: " + VesselChoices())
      ->required();
  cmd->add_option("--method", o->method,
                  "refit (the vessel's own coefficients), fossen-ceres (odin3dof) or eb-lr "
                  "(eb2dof)")
      ->required();
  cmd->add_option("--maneuvers", o->maneuvers,
                  "Maneuvers to compare, as `usvid simulate --maneuver` takes them")
      ->required()
      ->delimiter(',');
  cmd->add_option("--noise", o->noise,
                  "Measurement noise, a fraction of each channel's standard deviation on the "
                  "first maneuver (the same sensors for every maneuver)")
      ->capture_default_str();
  cmd->add_option("--parameters", o->parameters,
                  "Parameters of interest, as the method names them: the criteria are theirs, "
                  "the others nuisances (default: all)")
      ->delimiter(',');
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
