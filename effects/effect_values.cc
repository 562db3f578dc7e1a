#include "effects/effect_values.h"

#include <algorithm>
#include <bit>

#include "core/error.h"

namespace usvid {

uint32_t InputMask(const Effect& e, const std::vector<std::string>& input_names) {
  if (e.inputs.empty()) return ~0u;
  uint32_t mask = 0;
  for (const std::string& name : e.inputs) {
    size_t i = 0;
    while (i < input_names.size() && input_names[i] != name) ++i;
    if (i == input_names.size() || i >= 32) {
      std::string known;
      for (const std::string& n : input_names) known += (known.empty() ? "" : ", ") + n;
      throw InputError("effect " + std::string(e.name()) + ": '" + name +
                       "' is not an input of the vessel (inputs: " +
                       (known.empty() ? "none given" : known) + ")");
    }
    mask |= 1u << i;
  }
  return mask;
}

std::shared_ptr<const ResolvedTerm> ResolveTerm(const Effect& e,
                                                const std::vector<std::string>& state_names,
                                                const std::vector<std::string>& input_names) {
  auto index = [](const std::vector<std::string>& names, const std::string& name) {
    return static_cast<int>(std::find(names.begin(), names.end(), name) - names.begin());
  };
  auto known = [&] {
    std::string list;
    for (const auto* names : {&state_names, &input_names})
      for (const std::string& n : *names) list += (list.empty() ? "" : ", ") + n;
    return list.empty() ? std::string("none given") : list;
  };
  auto t = std::make_shared<ResolvedTerm>();
  t->state = index(state_names, e.state);
  if (t->state == static_cast<int>(state_names.size()))
    throw InputError("effect missing_term: '" + e.state +
                     "' is not a state of the vessel (states and inputs: " + known() + ")");
  t->term = Expression::Parse(e.term, "missing_term");
  for (const std::string& name : t->term.Variables()) {
    const int s = index(state_names, name), i = index(input_names, name);
    if (s < static_cast<int>(state_names.size()))
      t->slots.push_back(s);
    else if (i < static_cast<int>(input_names.size()))
      t->slots.push_back(static_cast<int>(state_names.size()) + i);
    else
      throw InputError("effect missing_term: the term '" + e.term + "' uses '" + name +
                       "', not a state or input of the vessel (" + known() + ")");
  }
  t->state_name = e.state;
  t->text = e.term;
  return t;
}

void SetEffect(const Effect& e, EffectValues<double>& v,
               const std::vector<std::string>& input_names,
               const std::vector<std::string>& state_names) {
  if (e.kind == EffectKind::kMissingTerm) {
    ExtraTerm<double> t{ResolveTerm(e, state_names, input_names), e.at("coefficient")};
    std::erase_if(v.extra_terms, [&](const ExtraTerm<double>& o) {
      return o.resolved->state_name == e.state && o.resolved->text == e.term;
    });
    v.extra_terms.push_back(std::move(t));
    return;
  }
  const uint32_t mask = InputMask(e, input_names);
  switch (e.kind) {
    case EffectKind::kInputDelay:
      if (e.inputs.empty()) {
        v.delay_s = e.at("delay_s");
      } else {
        v.input_delays_s.resize(input_names.size(), 0.0);
        for (size_t i = 0; i < input_names.size(); ++i)
          if ((mask >> i) & 1u) v.input_delays_s[i] = e.at("delay_s");
      }
      break;
    case EffectKind::kCurrent:
      v.current_north = e.at("current_north");
      v.current_east = e.at("current_east");
      break;
    case EffectKind::kActuatorLag:
      v.lag_time_constant_s = e.at("time_constant_s");
      v.lag_inputs = mask;
      break;
    case EffectKind::kInputBias:
      v.input_bias = e.at("bias");
      v.bias_input = -1;
      if (!e.inputs.empty()) {
        if (e.inputs.size() != 1)
          throw InputError("effect input_bias: acts on one input, got " +
                           std::to_string(e.inputs.size()));
        v.bias_input = std::countr_zero(mask);
      }
      break;
    case EffectKind::kSensorBias:
      v.sensor_bias = e.at("bias");
      break;
    case EffectKind::kInertia:
      v.inertia_scale = e.at("scale");
      break;
    case EffectKind::kDamping:
      v.damping_scale = e.at("scale");
      break;
    case EffectKind::kSaturation:
      v.saturation_fraction = e.at("fraction");
      v.saturation_inputs = mask;
      break;
    case EffectKind::kSurgeForce:
      v.surge_acceleration = e.at("acceleration");
      break;
    case EffectKind::kResistance:
      v.resistance_scale = e.at("scale");
      break;
    case EffectKind::kWind:
      v.wind_scale = e.at("scale");
      break;
    case EffectKind::kMissingTerm:
      break;  // above
  }
}

EffectValues<double> ValuesOf(const std::vector<Effect>& effects,
                              const std::vector<std::string>& input_names,
                              const std::vector<std::string>& state_names) {
  EffectValues<double> v;
  for (const Effect& e : effects) SetEffect(e, v, input_names, state_names);
  return v;
}

}  // namespace usvid
