#include "effects/effect_values.h"

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

void SetEffect(const Effect& e, EffectValues<double>& v,
               const std::vector<std::string>& input_names) {
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
  }
}

EffectValues<double> ValuesOf(const std::vector<Effect>& effects,
                              const std::vector<std::string>& input_names) {
  EffectValues<double> v;
  for (const Effect& e : effects) SetEffect(e, v, input_names);
  return v;
}

}  // namespace usvid
