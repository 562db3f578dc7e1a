// GP-SR identification of a whole model: one GP-OLS search per state derivative (after
// preprocessing), with the states and inputs as variables, on the first part of the record;
// then the model chosen among each search's Pareto candidates by short-horizon simulation on the
// rest, the validation part (model_selection.h), and the chosen terms refitted on every row, by
// equation error and then by simulation error (simulation_refit.h).
// The result is the model JSON of docs/data.md#modeljson (equations in channel names) plus, per
// equation, the Pareto front of held-out error against size, the generation log, why the search
// stopped, and which candidate was chosen and why.
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "methods/gp/search.h"
#include "methods/regime_features.h"
#include "preprocessing/pipeline.h"

namespace usvid::gp {

// The name --method and suites give it (methods/method_list.h registers it).
inline constexpr std::string_view kMethodName = "gp";

// "+,-,*,abs,tanh,/" -> functions; throws InputError naming an unknown operator.
std::vector<Op> ParseOperators(const std::string& list);
std::string OperatorList(const std::vector<Op>& ops);

// How the chosen terms' weights are fitted on every row: by equation error (least squares on
// the derivatives), or by that and then by simulation error (simulation_refit.h).
enum class WeightFit { kEquation, kSimulation };

// Which chosen equations the simulation refit offers a linear damping term in their own state
// (gp_identify.cc, RefineWithDamping): those that do not damp it on average over some record
// (model.json's "undamped"), those that do not damp it at every row, or none.
enum class DampingOffer { kUndamped, kEveryRow, kNone };

struct GpIdentifyOptions {
  GpOptions search;
  double validation_fraction = 0.2;  // the record's last part; 0: the search's best is kept
  double horizon_s = 10.0;           // of the short-horizon simulations
  WeightFit weight_fit = WeightFit::kSimulation;         // needs a validation part
  DampingOffer damping_offer = DampingOffer::kUndamped;  // with the simulation refit
  // With the simulation refit: u' offered v*r and v' u*r where the chosen equation lacks it.
  bool kinematics_offer = false;
  // Variables computed from the states (regime_features.h): searched like any other, written
  // into the equations as their expressions, recomputed from the simulated states when
  // candidates are simulated.
  std::vector<DerivedVariable> features;
  // Each candidate also offered with the regime features, `completion_features` and the
  // products of two states added, and its terms chosen again (term_completion.h). usvid
  // identify turns it on with regime features.
  bool complete_terms = false;
  // Variables offered to term completion but not to the search (a finer regime basis).
  std::vector<DerivedVariable> completion_features;
};

struct GpIdentification {
  nlohmann::json equations = nlohmann::json::object();   // state -> expression of its derivative
  nlohmann::json parameters = nlohmann::json::object();  // "<state>.bias", "<state>.w1", ...
  nlohmann::json details = nlohmann::json::object();     // per state: r2, size, pareto, log
  double node_evaluations = 0.0;
};

// One equation per state in `states`; the variables are `variables` (states that enter the
// dynamics, e.g. the msd's position x, which needs no equation of its own), `inputs` and
// options.features. Throws InputError for a feature whose expression names a missing channel.
// progress(state, log) after each generation.
GpIdentification IdentifyWithGp(
    const PreparedData& prepared, const std::vector<std::string>& states,
    const std::vector<std::string>& variables, const std::vector<std::string>& inputs,
    const GpIdentifyOptions& options,
    const std::function<void(const std::string&, const GenerationLog&)>& progress = {});

}  // namespace usvid::gp
