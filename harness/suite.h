// A comparison suite (usvid compare --suite S.json): vessels x training maneuvers x test
// maneuvers x methods x noise levels x seeds. Every score is on data the model was not fitted
// on: another maneuver, or the same maneuver with another seed. JSON form:
//   {"name": "...", "vessels": ["odin3dof"], "train_maneuvers": ["random-steps"],
//    "test_maneuvers": ["multisine"], "methods": [NAME, or {"method": NAME, options...}],
//    "noise": [0.005], "seeds": [1, 2, 3], "train_seconds": 300, "test_seconds": 180,
//    "effects": ["current=0.3"], "sensors": ["imu=50", "gps=5"]}
// ("effects", "sensors", "gusts", "waves" and "dropouts" optional: SuiteConditions)
// (a method's options are those it declares, docs/options.md, with the keys every method
// shares: states, inputs, rate, forces and derivative; harness/suites/default.json is an
// example).
// Or, on measured data (suite_data.h), the training and test files instead of maneuvers:
//   {"name": "kvlcc2-marin", "vessels": ["kvlcc2"], "data": {"train": [{"name": ...,
//    "file": ..., "format": "marin-dat"}], "test": [...]}, "methods": [...]}
// with at most one vessel (whose channels the files hold; none when the methods name their
// "states" and "inputs"), maneuver names taken from the data names, no added noise.
// "cv": "runs" (measured data only; usvid compare --cv runs) cross-validates over the runs
// instead: each run left out in turn, every method fitted on the others jointly and scored on it
// (harness/cross_validation.h); "test" may then be left out.
// "pairs": [[A, B], ...] (optional, any suite; A and B method names): pairs the verdict tests
// head to head on each vessel and training maneuver, beside its ranking (harness/verdict.h,
// PairTest).
// A vessel is a compiled-in name or a vessel file (docs/model.md#vessel-files), a relative path
// taken from the suite file's folder, as the data files are.
// Methods: every method of the suite's registry (harness/suite_methods.h): the registered
// identification methods (methods/method_list.h), diagnose (the nominal vessel extended by the
// causes `usvid diagnose` names on the training data), and external commands
// ({"method": "external", "name": ..., "command": [...]}; harness/external_method.h).
// Unknown fields, wrong types and unknown names are errors naming the file and field. Every field,
// its default and what it holds: harness/suite_fields.h (docs/suites.md, generated).
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "harness/external_method.h"
#include "harness/fit_service.h"
#include "harness/suite_data.h"
#include "harness/suite_methods.h"
#include "methods/method_options.h"
#include "simulation/vessel_ref.h"

namespace usvid {

struct SuiteMethod {
  std::string method;      // a method of SuiteMethods() (harness/suite_methods.h)
  nlohmann::json options;  // its options and the shared keys, as the suite gives them
  std::string Label() const;
  // `options` less the shared keys (SharedFitOptions, harness/fit_service.h): the method's own, as
  // declared.
  nlohmann::json OwnOptions() const;
};

// What every simulated record of a suite holds besides its maneuver and noise, the same for its
// training and test records (docs/compare.md#conditions): effects hidden in the plant (effect
// specs as `usvid simulate --effect` takes them, docs/data.md#effects; a current's direction,
// when not given, drawn from each record's seed), which the methods are not told of, and sensors
// sampled slower than the output rate (`usvid simulate --rates` items: "imu=50", "gps=5"; the
// output rate is raised to the fastest).
struct SuiteConditions {
  std::vector<std::string> effects;   // `simulate --effect` items
  std::vector<std::string> sensors;   // `simulate --rates` items
  std::string gusts;                  // `simulate --gusts` (simulation/wind_gusts.h); "": none
  std::string waves;                  // `simulate --waves` (sensors/wave_motion.h); "": calm
  std::vector<std::string> dropouts;  // `simulate --dropouts` items (sensors/dropouts.h)
  // `simulate --logged` items (simulation/logged_disturbances.h): the disturbances the records
  // log, and the equation methods read as inputs; the others stay hidden.
  std::vector<std::string> logged;
  bool empty() const {
    return effects.empty() && sensors.empty() && gusts.empty() && waves.empty() &&
           dropouts.empty() && logged.empty();
  }
};

// Leave-one-run-out cross-validation of a suite on measured data (harness/cross_validation.h).
struct SuiteCrossValidation {
  std::string kind;                                // "" (none) or "runs"
  std::vector<SuiteData> given_train, given_test;  // the data entries as the suite gave them
  // Each fold's training name ("all but R") -> the run R it leaves out and is scored on.
  std::map<std::string, std::string> held_out;
  bool On() const { return !kind.empty(); }
};

struct Suite {
  std::string name = "suite";
  std::vector<VesselRef> vessels;  // resolved as the suite is read
  std::vector<std::string> train_maneuvers, test_maneuvers;
  std::vector<SuiteMethod> methods;
  std::vector<double> noise;
  std::vector<uint64_t> seeds;
  double train_seconds = 300.0;
  double test_seconds = 180.0;
  SuiteConditions conditions;  // simulated suites only
  // Measured data (train_maneuvers and test_maneuvers then hold their names). Cross-validated
  // (cv): test_data holds every run, one file each, and train_maneuvers the folds' names.
  std::vector<SuiteData> train_data, test_data;
  SuiteCrossValidation cv;
  // "pairs": two methods each (by name, each among "methods") that the verdict also tests head
  // to head on every table (harness/verdict.h, PairTest).
  std::vector<std::array<std::string, 2>> pairs;
  bool Measured() const { return !train_data.empty(); }
};

// One fit: a method trained on one vessel's maneuver at a noise level and seed.
struct FitJob {
  VesselRef vessel;
  std::string train_maneuver;
  SuiteMethod method;
  double noise = 0.0;
  uint64_t seed = 1;
  std::string Id() const;
};

// A method entry checked, before any fit: the method is one of SuiteMethods(), its options are
// the shared keys and those it declares (names, types, ranges; a derivative spec parsed; an
// external command's name not a method's). Throws InputError, one line naming `where`, the
// method, the key and what is allowed.
void CheckSuiteMethod(const SuiteMethod& method, const std::string& where);

// Every field read through its one declaration (harness/suite_fields.h): relative data and
// vessel paths taken from the folder of `file`; then the conditions checked together
// (CheckSuiteConditions). SuiteToJson writes the suite back through the same declarations.
Suite ParseSuite(const nlohmann::json& value, const std::string& file);
nlohmann::json SuiteToJson(const Suite& suite);

// "effects", "sensors", "gusts", "waves", "dropouts" and "logged" checked together, on every
// vessel of the suite, before any fit: an effect the vessel cannot take (wind without a wind
// model, an input or state it lacks), waves on a vessel without positions and body velocities, a
// sensor naming no group or channel of its records, or a logged disturbance that the conditions
// do not make is an error naming the field. Nothing to check without conditions.
void CheckSuiteConditions(const Suite& suite, const std::string& file);

// The fits a suite needs: every method on every training maneuver of every vessel that can run
// it (a zig-zag needs a heading, a step grid a thrust input). Combinations a method cannot fit
// become rows saying why.
std::vector<FitJob> FitJobs(const Suite& suite);

}  // namespace usvid
