// model.json as its readers take it (docs/data.md#modeljson): every key a reader of a model needs
// is named here once, with what its absence means. A method writes its model as JSON (its own
// details under its own key); everything that reads one (the metrics' free runs and replays, the
// calibration, the harness's rows, the command line, the design's checks) reads it through this
// view, so a key renamed or a default changed is one edit. ModelView reads; ModelEdit, over a
// model being finished (metrics/yaw_bias_calibration.h, metrics/closed_loop_choice.h), also
// writes the keys those steps set.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace usvid {

// A model's equations: each state and its right-hand side as written (core/expression.h).
using EquationList = std::vector<std::pair<std::string, std::string>>;

// One of the models a grey-box fit weighed (methods/gp/grey_box.h), as model.json lists it under
// "alternatives": the first is the vessel as given.
struct ModelAlternative {
  nlohmann::json label;
  nlohmann::json effects;         // as a vessel model's "effects"
  nlohmann::json corrections;     // the same, readable
  nlohmann::json free_run_error;  // held-out; null when its free runs failed
  // free_run_error, infinite when null.
  double FreeRunError() const;
};

class ModelView {
 public:
  explicit ModelView(const nlohmann::json& model) : m_(model) {}

  // "method", the method that wrote the model; `fallback` when absent or not a string.
  std::string Method(const std::string& fallback = "") const;
  // "vessel" when a non-empty string, else "".
  std::string Vessel() const;
  // A vessel model (refit, hybrid, nominal, diagnose): no "equations", and a "vessel" that is
  // not null or "" (VesselModelName checks it is a name).
  bool IsVesselModel() const;
  // A vessel model's vessel; InputError when "vessel" is not a string.
  std::string VesselModelName() const;
  // An equation model: it has "equations" (EquationModel checks them).
  bool HasEquations() const { return m_.contains("equations"); }
  // The states with equations, in the model's order; empty for a vessel model.
  std::vector<std::string> EquationStates() const;
  // Each state's equation as written; InputError when "equations" is not a non-empty object of
  // strings.
  EquationList Equations() const;
  // The equation of `state`; nullopt when the model has none for it.
  std::optional<std::string> Equation(const std::string& state) const;
  // "states": every state of a vessel model (and an equation model's).
  std::vector<std::string> States() const;
  // "inputs": the channels that drove the fit; empty when absent.
  std::vector<std::string> Inputs() const;
  // "variables": the channels the equations read besides the inputs; nullopt when absent.
  std::optional<std::vector<std::string>> Variables() const;
  // "parameters": an object of name: value; null when absent.
  const nlohmann::json& Parameters() const;
  // One of them; nullopt when absent.
  std::optional<double> Parameter(const std::string& name) const;
  // "preprocessing"."forces": the input map the fit was driven through ("waterjet"), "" for none.
  std::string Forces() const;
  // "preprocessing"."delay_s": the inputs' delay the fit used [s]; 0 when absent.
  double DelaySeconds() const;
  // "length_m": a hull length the model states [m].
  std::optional<double> LengthM() const;
  // "effects": a vessel model's effects (effects/effect.h, as JSON); empty when absent, InputError
  // when not an array.
  std::vector<nlohmann::json> Effects() const;
  // "alternatives": the models a grey-box fit weighed; empty when absent.
  std::vector<ModelAlternative> Alternatives() const;
  // "calibration"."<step>": what the method asks of a step after its fit ("closed-loop",
  // "zigzag"), or that step's report once run; null when absent.
  const nlohmann::json& Calibration(const std::string& step) const;
  // "train"."seconds": how long the fit took [s]; 0 when absent.
  double TrainSeconds() const;
  // A section by its key: a method's own details, under its name (refit, eb_lr, gp, ...),
  // or the options it ran with ("options"); null when absent.
  const nlohmann::json& Section(const std::string& key) const;

  const nlohmann::json& Json() const { return m_; }

 private:
  const nlohmann::json& m_;
};

class ModelEdit : public ModelView {
 public:
  explicit ModelEdit(nlohmann::json& model) : ModelView(model), w_(model) {}

  void SetEquation(const std::string& state, const std::string& text);
  // Sets a parameter the model already has; one it lacks is left out.
  void UpdateParameter(const std::string& name, double value);
  // A vessel model's effects, and their readable corrections (methods/gp/grey_box.h).
  void SetEffects(const nlohmann::json& effects);
  void SetCorrections(const nlohmann::json& corrections);
  void SetCalibration(const std::string& step, nlohmann::json report);

 private:
  nlohmann::json& w_;
};

}  // namespace usvid
