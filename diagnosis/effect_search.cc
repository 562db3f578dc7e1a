#include "diagnosis/effect_search.h"

#include <cmath>

namespace usvid::diagnosis {

EffectSearch SearchFor(EffectKind kind, const MeasuredData& data, int yaw_input, int input) {
  EffectSearch s{kind, OnInputs(kind) ? input : -1, true, {}, {}, {}, {}, {}};
  auto add = [&s](std::string name, double start, double lower, double upper) {
    s.names.push_back(std::move(name));
    s.start.push_back(start);
    s.lower.push_back(lower);
    s.upper.push_back(upper);
  };
  switch (kind) {
    case EffectKind::kInputDelay:
      s.smooth = false;
      add("delay_s", 0.0, 0.0, 3.0);
      break;
    case EffectKind::kCurrent:
      add("current_north", 0.0, -3.0, 3.0);
      add("current_east", 0.0, -3.0, 3.0);
      break;
    case EffectKind::kActuatorLag:
      // Below one integration step RK4 would not follow the lag (and it is a delay by then).
      add("time_constant_s", 0.5, std::max(0.02, data.max_step), 30.0);
      break;
    case EffectKind::kInputBias: {
      const double peak = std::max(data.peak_command[input >= 0 ? input : yaw_input], 1e-9);
      add("bias", 0.0, -peak, peak);
      break;
    }
    case EffectKind::kSensorBias: {
      double peak = 0.0;
      if (data.rate_channel >= 0) peak = data.measured.col(data.rate_channel).cwiseAbs().maxCoeff();
      add("bias", 0.0, -(peak + 0.1), peak + 0.1);
      break;
    }
    case EffectKind::kInertia:
      add("scale", 1.0, 0.2, 5.0);
      break;
    case EffectKind::kDamping:
      add("scale", 1.0, 0.2, 5.0);
      break;
    case EffectKind::kSaturation:
      s.smooth = false;
      add("fraction", 1.0, 0.05, 1.0);
      break;
    case EffectKind::kSurgeForce:
      add("acceleration", 0.0, -0.5, 0.5);
      break;
    case EffectKind::kResistance:
      add("scale", 1.0, 0.2, 5.0);
      break;
    case EffectKind::kWind:
      // From none: the wind force the model lacks, as a multiple of its wind model; below 0,
      // a model whose wind is too strong.
      add("scale", 0.0, -2.0, 4.0);
      break;
    case EffectKind::kMissingTerm:
      break;  // SearchForTerm
  }
  return s;
}

EffectSearch SearchForTerm(const Effect& effect, const std::vector<std::string>& state_names,
                           const std::vector<std::string>& input_names) {
  EffectSearch s{EffectKind::kMissingTerm, -1, true, {}, {}, {}, {}, {}};
  s.term = ResolveTerm(effect, state_names, input_names);
  const double start = effect.at("coefficient"), reach = 10.0 * std::abs(start) + 1e-6;
  s.names = {"coefficient"};
  s.start = {start};
  s.lower = {-reach};
  s.upper = {reach};
  return s;
}

std::vector<std::string> SizeNames(EffectKind kind) {
  if (kind == EffectKind::kCurrent) return {"current_north", "current_east"};
  return {std::string(InfoOf(kind).main_parameter)};
}

Effect EffectOf(const EffectSearch& search, const std::vector<double>& theta,
                const std::vector<std::string>& input_names) {
  Effect e{search.kind, {}};
  const std::vector<std::string> names = SizeNames(search.kind);
  for (size_t i = 0; i < names.size(); ++i) e.parameters[names[i]] = theta.at(i);
  if (search.input >= 0) e.inputs = {input_names.at(search.input)};
  if (search.kind == EffectKind::kMissingTerm) {
    e.state = search.term->state_name;
    e.term = search.term->text;
  }
  return e;
}

}  // namespace usvid::diagnosis
