#include "effects/effect.h"

#include <cmath>
#include <numbers>
#include <random>

#include "core/error.h"
#include "core/expression.h"
#include "core/json_file.h"
#include "core/parse_number.h"

namespace usvid {
namespace {

constexpr std::array<EffectInfo, 11> kCatalogue = {{
    {EffectKind::kInputDelay, "input_delay", "delay_s",
     "every input reaches the plant late by a constant time"},
    {EffectKind::kCurrent, "current", "speed",
     "constant irrotational ocean current; damping acts on the relative velocity"},
    {EffectKind::kActuatorLag, "actuator_lag", "time_constant_s",
     "first-order lag between commanded and applied input"},
    {EffectKind::kInputBias, "input_bias", "bias",
     "constant offset added to the yaw input (misaligned jets / nozzle zero)"},
    {EffectKind::kSensorBias, "sensor_bias", "bias",
     "constant offset on the measured yaw rate r (gyro bias)"},
    {EffectKind::kInertia, "inertia", "scale", "mass and inertia matrix off by a common factor"},
    {EffectKind::kDamping, "damping", "scale", "damping matrix off by a common factor"},
    {EffectKind::kSaturation, "saturation", "fraction",
     "each input clipped at +-fraction x its peak absolute command in the data"},
    {EffectKind::kSurgeForce, "surge_force", "acceleration",
     "constant surge force missing from the model (propulsion mismatch, a towing force), as an "
     "acceleration [m/s^2]"},
    {EffectKind::kResistance, "resistance", "scale",
     "surge resistance off by a factor (the rest of the damping as modelled)"},
    {EffectKind::kWind, "wind", "scale",
     "the measured relative wind's force, as a multiple of the vessel's wind model, missing "
     "from the model"},
}};

constexpr EffectInfo kMissingTermInfo = {
    EffectKind::kMissingTerm, "missing_term", "coefficient",
    "a term coefficient x TERM missing from one state's derivative (beyond the catalogue)"};

// The effect called `name`, in the catalogue or missing_term; nullptr for none.
const EffectInfo* FindInfo(const std::string& name) {
  for (const EffectInfo& e : kCatalogue)
    if (e.name == name) return &e;
  return name == kMissingTermInfo.name ? &kMissingTermInfo : nullptr;
}

std::string KnownNames() {
  std::string names;
  for (const EffectInfo& e : kCatalogue) names += (names.empty() ? "" : ", ") + std::string(e.name);
  return names + ", " + std::string(kMissingTermInfo.name);
}

// A missing term's text: it must parse as an expression (core/expression.h).
void CheckTerm(const std::string& term, const std::string& where) {
  if (term.empty()) throw InputError(where + "missing_term: an empty term");
  (void)Expression::Parse(term, where + "missing_term '" + term + "'");
}

// Checks the main value against the effect's rule; returns the rule broken, or "".
std::string Violation(EffectKind kind, double value) {
  switch (kind) {
    case EffectKind::kInputDelay:
      return value >= 0.0 && value <= 10.0 ? "" : "delay_s must be in [0, 10] s";
    case EffectKind::kCurrent:
      return value >= 0.0 && value <= 5.0 ? "" : "current speed must be in [0, 5] m/s";
    case EffectKind::kActuatorLag:
      return value > 0.0 && value <= 60.0 ? "" : "time_constant_s must be in (0, 60] s";
    case EffectKind::kInputBias:
    case EffectKind::kSensorBias:
      return "";
    case EffectKind::kInertia:
    case EffectKind::kDamping:
    case EffectKind::kResistance:
      return value > 0.0 && value <= 100.0 ? "" : "scale must be in (0, 100]";
    case EffectKind::kSaturation:
      return value > 0.0 && value <= 1.0 ? "" : "fraction must be in (0, 1]";
    case EffectKind::kSurgeForce:
      return std::abs(value) <= 5.0 ? "" : "acceleration must be in [-5, 5] m/s^2";
    case EffectKind::kWind:
      return std::abs(value) <= 10.0 ? "" : "scale must be in [-10, 10]";
    case EffectKind::kMissingTerm:
      return std::isfinite(value) ? "" : "coefficient must be finite";
  }
  return "";
}

double ParseValue(const std::string& text, const std::string& where) {
  const ParsedNumber p = ParseNumber(text);
  if (p.status != NumberStatus::kOk) throw InputError(where + DescribeNumberStatus(p.status, text));
  return p.value;
}

}  // namespace

const std::array<EffectInfo, 11>& EffectCatalogue() { return kCatalogue; }

const EffectInfo& InfoOf(EffectKind kind) {
  return kind == EffectKind::kMissingTerm ? kMissingTermInfo
                                          : kCatalogue[static_cast<size_t>(kind)];
}

bool OnInputs(EffectKind kind) {
  return kind == EffectKind::kInputDelay || kind == EffectKind::kActuatorLag ||
         kind == EffectKind::kInputBias || kind == EffectKind::kSaturation;
}

std::string EffectLabel(const Effect& effect) {
  std::string label(effect.name());
  if (effect.kind == EffectKind::kMissingTerm)
    return label + " " + effect.state + ": " + effect.term;
  for (size_t i = 0; i < effect.inputs.size(); ++i) label += (i ? "+" : "@") + effect.inputs[i];
  return label;
}

Effect ParseEffect(const std::string& full_spec, uint64_t seed) {
  const std::string where = "--effect '" + full_spec + "': ";
  std::string spec = full_spec;
  std::vector<std::string> inputs;
  if (const auto at = spec.find('@'); at != std::string::npos) {
    const std::string list = spec.substr(at + 1);
    spec = spec.substr(0, at);
    for (size_t a = 0; a <= list.size();) {
      const size_t b = std::min(list.find('+', a), list.size());
      if (b == a) throw InputError(where + "an empty input name after '@' (NAME=VALUE@IN1+IN2)");
      inputs.push_back(list.substr(a, b - a));
      a = b + 1;
    }
  }
  const auto eq = spec.find('=');
  const std::string name = spec.substr(0, eq);
  const EffectInfo* info = FindInfo(name);
  if (info == nullptr)
    throw InputError(where + "unknown effect '" + name + "' (known: " + KnownNames() + ")");
  if (eq == std::string::npos) throw InputError(where + "expected NAME=VALUE");
  std::string value_text = spec.substr(eq + 1);
  std::string direction_text, state, term;
  if (info->kind == EffectKind::kMissingTerm) {
    const auto first = value_text.find(':');
    const auto second = first == std::string::npos ? first : value_text.find(':', first + 1);
    if (second == std::string::npos)
      throw InputError(where + "expected missing_term=COEFFICIENT:STATE:TERM");
    state = value_text.substr(first + 1, second - first - 1);
    term = value_text.substr(second + 1);
    value_text = value_text.substr(0, first);
    if (state.empty()) throw InputError(where + "missing_term: an empty state name");
    CheckTerm(term, where);
  }
  if (info->kind == EffectKind::kCurrent) {
    const auto colon = value_text.find(':');
    if (colon != std::string::npos) {
      direction_text = value_text.substr(colon + 1);
      value_text = value_text.substr(0, colon);
    }
  }
  const double value = ParseValue(value_text, where);
  if (const std::string rule = Violation(info->kind, value); !rule.empty())
    throw InputError(where + rule);

  if (!inputs.empty() && !OnInputs(info->kind))
    throw InputError(where + name +
                     " acts on the whole vessel, not on inputs (only input_delay, actuator_lag, "
                     "input_bias and saturation take @INPUT)");
  Effect effect{info->kind, {}, inputs, state, term};
  if (info->kind == EffectKind::kCurrent) {
    double direction = 0.0;
    if (!direction_text.empty()) {
      direction = ParseValue(direction_text, where) * std::numbers::pi / 180.0;
    } else {
      std::mt19937_64 rng(seed ^ 0xC0FFEEull);
      direction = std::uniform_real_distribution<double>(0.0, 2 * std::numbers::pi)(rng);
    }
    effect.parameters["current_north"] = value * std::cos(direction);
    effect.parameters["current_east"] = value * std::sin(direction);
  } else {
    effect.parameters[std::string(info->main_parameter)] = value;
  }
  return effect;
}

std::vector<Effect> ParseEffects(const std::vector<std::string>& specs, uint64_t seed) {
  std::vector<Effect> effects;
  for (const std::string& spec : specs) {
    Effect e = ParseEffect(spec, seed);
    for (const Effect& other : effects)
      if (SameEffect(other, e)) throw InputError("--effect '" + spec + "': given twice");
    effects.push_back(std::move(e));
  }
  return effects;
}

bool SameEffect(const Effect& a, const Effect& b) {
  return a.kind == b.kind && a.inputs == b.inputs && a.state == b.state && a.term == b.term;
}

nlohmann::json EffectToJson(const Effect& effect) {
  nlohmann::json j = {{"effect", effect.name()}, {"parameters", effect.parameters}};
  if (!effect.inputs.empty()) j["inputs"] = effect.inputs;
  if (effect.kind == EffectKind::kMissingTerm) {
    j["state"] = effect.state;
    j["term"] = effect.term;
  }
  return j;
}

Effect EffectFromJson(const nlohmann::json& value) {
  if (!value.is_object() || !value.contains("effect") || !value.at("effect").is_string() ||
      !value.contains("parameters") || !value.at("parameters").is_object())
    throw InputError("an effect is {\"effect\": NAME, \"parameters\": {NAME: NUMBER, ...}}");
  const std::string name = value.at("effect").get<std::string>();
  const EffectInfo* info = FindInfo(name);
  if (info == nullptr)
    throw InputError("unknown effect '" + name + "' (known: " + KnownNames() + ")");
  const EffectInfo& e = *info;
  Effect effect{e.kind, {}};
  for (const auto& [key, v] : value.at("parameters").items()) {
    if (!v.is_number() || !std::isfinite(v.get<double>()))
      throw InputError("effect " + name + ": parameter '" + key + "' is not a finite number");
    effect.parameters[key] = v.get<double>();
  }
  const std::vector<std::string> needed =
      e.kind == EffectKind::kCurrent ? std::vector<std::string>{"current_north", "current_east"}
                                     : std::vector<std::string>{std::string(e.main_parameter)};
  for (const std::string& n : needed)
    if (!effect.parameters.contains(n))
      throw InputError("effect " + name + ": no parameter '" + n + "'");
  if (value.contains("inputs")) {
    const nlohmann::json& in = value.at("inputs");
    bool names = in.is_array() && !in.empty();
    for (const auto& i : in) names = names && i.is_string() && !i.get<std::string>().empty();
    if (!names) throw InputError("effect " + name + ": \"inputs\" is a list of input names");
    if (!OnInputs(e.kind))
      throw InputError("effect " + name + ": acts on the whole vessel, it takes no \"inputs\"");
    effect.inputs = in.get<std::vector<std::string>>();
  }
  if (e.kind == EffectKind::kMissingTerm) {
    for (const char* key : {"state", "term"})
      if (!value.contains(key) || !value.at(key).is_string() ||
          value.at(key).get<std::string>().empty())
        throw InputError("effect missing_term: \"" + std::string(key) + "\" is not a name");
    effect.state = value.at("state").get<std::string>();
    effect.term = value.at("term").get<std::string>();
    CheckTerm(effect.term, "effect ");
  }
  return effect;
}

std::vector<Effect> EffectsOfFile(const std::string& path) {
  const nlohmann::json j = ReadJsonFile(path);
  std::vector<Effect> effects;
  if (!j.is_object() || !j.contains("effects")) return effects;
  if (!j.at("effects").is_array()) throw InputError(path + ": \"effects\" is not an array");
  for (const auto& e : j.at("effects")) {
    try {
      effects.push_back(EffectFromJson(e));
    } catch (const InputError& err) {
      throw InputError(path + ": effects: " + err.what());
    }
  }
  return effects;
}

std::vector<Effect> MergeEffects(std::vector<Effect> base, const std::vector<Effect>& overrides) {
  for (const Effect& o : overrides) {
    std::erase_if(base, [&o](const Effect& b) { return SameEffect(b, o); });
    base.push_back(o);
  }
  return base;
}

}  // namespace usvid
