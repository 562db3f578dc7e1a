#include "effects/effect_values.h"

namespace usvid {

void SetEffect(const Effect& e, EffectValues<double>& v) {
  switch (e.kind) {
    case EffectKind::kInputDelay:
      v.delay_s = e.at("delay_s");
      break;
    case EffectKind::kCurrent:
      v.current_north = e.at("current_north");
      v.current_east = e.at("current_east");
      break;
    case EffectKind::kActuatorLag:
      v.lag_time_constant_s = e.at("time_constant_s");
      break;
    case EffectKind::kInputBias:
      v.input_bias = e.at("bias");
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
      break;
    case EffectKind::kSurgeForce:
      v.surge_acceleration = e.at("acceleration");
      break;
    case EffectKind::kResistance:
      v.resistance_scale = e.at("scale");
      break;
  }
}

EffectValues<double> ValuesOf(const std::vector<Effect>& effects) {
  EffectValues<double> v;
  for (const Effect& e : effects) SetEffect(e, v);
  return v;
}

}  // namespace usvid
