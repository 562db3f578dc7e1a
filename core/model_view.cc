#include "core/model_view.h"

#include <limits>

#include "core/error.h"

namespace usvid {
namespace {

const nlohmann::json& Null() {
  static const nlohmann::json null;
  return null;
}

// m[key] when m is an object holding it, else null.
const nlohmann::json& Member(const nlohmann::json& m, const std::string& key) {
  if (!m.is_object()) return Null();
  const auto it = m.find(key);
  return it == m.end() ? Null() : *it;
}

std::vector<std::string> Names(const nlohmann::json& list) {
  std::vector<std::string> out;
  if (list.is_array())
    for (const nlohmann::json& n : list) out.push_back(n.get<std::string>());
  return out;
}

}  // namespace

std::string ModelView::Method(const std::string& fallback) const {
  const nlohmann::json& m = Member(m_, "method");
  return m.is_string() ? m.get<std::string>() : fallback;
}

std::string ModelView::Vessel() const {
  const nlohmann::json& v = Member(m_, "vessel");
  return v.is_string() ? v.get<std::string>() : "";
}

bool ModelView::IsVesselModel() const {
  const nlohmann::json& v = Member(m_, "vessel");
  return !HasEquations() && !v.is_null() && v != "";
}

std::string ModelView::VesselModelName() const {
  const nlohmann::json& v = Member(m_, "vessel");
  if (!v.is_string()) throw InputError("model: \"vessel\" is not a string");
  return v.get<std::string>();
}

std::vector<std::string> ModelView::EquationStates() const {
  std::vector<std::string> states;
  const nlohmann::json& eq = Member(m_, "equations");
  if (eq.is_object())
    for (const auto& [state, _] : eq.items()) states.push_back(state);
  return states;
}

EquationList ModelView::Equations() const {
  const nlohmann::json& eq = Member(m_, "equations");
  if (!eq.is_object() || eq.empty()) throw InputError("model: no \"equations\" object");
  EquationList out;
  for (const auto& [state, text] : eq.items()) {
    if (!text.is_string()) throw InputError("model: equation for '" + state + "' is not a string");
    out.emplace_back(state, text.get<std::string>());
  }
  return out;
}

std::optional<std::string> ModelView::Equation(const std::string& state) const {
  const nlohmann::json& text = Member(Member(m_, "equations"), state);
  if (!text.is_string()) return std::nullopt;
  return text.get<std::string>();
}

std::vector<std::string> ModelView::States() const { return Names(Member(m_, "states")); }

std::vector<std::string> ModelView::Inputs() const { return Names(Member(m_, "inputs")); }

std::optional<std::vector<std::string>> ModelView::Variables() const {
  const nlohmann::json& v = Member(m_, "variables");
  if (v.is_null()) return std::nullopt;
  return v.get<std::vector<std::string>>();
}

const nlohmann::json& ModelView::Parameters() const { return Member(m_, "parameters"); }

std::optional<double> ModelView::Parameter(const std::string& name) const {
  const nlohmann::json& p = Member(Parameters(), name);
  if (!p.is_number()) return std::nullopt;
  return p.get<double>();
}

std::string ModelView::Forces() const {
  const nlohmann::json& f = Member(Member(m_, "preprocessing"), "forces");
  return f.is_string() ? f.get<std::string>() : "";
}

double ModelView::DelaySeconds() const {
  const nlohmann::json& d = Member(Member(m_, "preprocessing"), "delay_s");
  return d.is_number() ? d.get<double>() : 0.0;
}

std::optional<double> ModelView::LengthM() const {
  const nlohmann::json& l = Member(m_, "length_m");
  if (!l.is_number()) return std::nullopt;
  return l.get<double>();
}

std::vector<nlohmann::json> ModelView::Effects() const {
  const nlohmann::json& e = Member(m_, "effects");
  if (e.is_null()) return {};
  if (!e.is_array()) throw InputError("model: \"effects\" is not an array");
  return {e.begin(), e.end()};
}

double ModelAlternative::FreeRunError() const {
  return free_run_error.is_number() ? free_run_error.get<double>()
                                    : std::numeric_limits<double>::infinity();
}

std::vector<ModelAlternative> ModelView::Alternatives() const {
  std::vector<ModelAlternative> out;
  const nlohmann::json& list = Member(m_, "alternatives");
  if (list.is_array())
    for (const nlohmann::json& a : list)
      out.push_back({Member(a, "label"), Member(a, "effects"), Member(a, "corrections"),
                     Member(a, "free_run_error")});
  return out;
}

const nlohmann::json& ModelView::Calibration(const std::string& step) const {
  return Member(Member(m_, "calibration"), step);
}

double ModelView::TrainSeconds() const {
  const nlohmann::json& s = Member(Member(m_, "train"), "seconds");
  return s.is_number() ? s.get<double>() : 0.0;
}

const nlohmann::json& ModelView::Section(const std::string& key) const {
  return Member(m_, key);
}

void ModelEdit::SetEquation(const std::string& state, const std::string& text) {
  w_["equations"][state] = text;
}

void ModelEdit::UpdateParameter(const std::string& name, double value) {
  if (Parameter(name)) w_["parameters"][name] = value;
}

void ModelEdit::SetEffects(const nlohmann::json& effects) { w_["effects"] = effects; }

void ModelEdit::SetCorrections(const nlohmann::json& corrections) {
  w_["corrections"] = corrections;
}

void ModelEdit::SetCalibration(const std::string& step, nlohmann::json report) {
  w_["calibration"][step] = std::move(report);
}

}  // namespace usvid
