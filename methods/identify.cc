#include "methods/identify.h"

#include <stdexcept>

#include "core/derived_channels.h"
#include "core/model_view.h"
#include "core/parse_number.h"
#include "methods/registry.h"
#include "methods/self_damping.h"
#include "preprocessing/waterjet_forces.h"

namespace usvid {

MethodOptions CheckedOptions(const Method& method, const IdentifyRequest& request,
                             const std::string& where) {
  return ValidateOptions(method.name, method.options, request.options, where);
}

nlohmann::json Identify(const Method& method, Dataset data, const IdentifyRequest& o,
                        const Logger& log) {
  const MethodOptions options = CheckedOptions(method, o, "");
  // Speed and course where only body velocities were logged (the 2-DOF models need them), and
  // the relative wind's body components where its speed and direction were.
  AddDerivedChannels(data);
  AddForces(data, o.preprocess.forces);
  nlohmann::json model = method.identify(data, o, options, log);
  if (const std::vector<std::string> unread = options.Unread(); !unread.empty())
    throw std::logic_error("method " + method.name + " declares option '" + unread.front() +
                           "' but did not read it");
  // A preset may say more of its options than were given.
  if (ModelView(model).Section("options").is_null()) model["options"] = options.Json();
  if (!ModelView(model).EquationStates().empty()) {
    const EquationList equations = ModelView(model).Equations();
    const std::map<std::string, double> damping = SelfDamping(equations, data);
    const std::map<std::string, double> straight = StraightRunningDamping(equations, data);
    nlohmann::json undamped = nlohmann::json::array();
    for (const auto& [state, d] : damping) {
      const auto at = straight.find(state);
      const bool straight_damped = at == straight.end() || at->second < 0;
      if (d < 0 && straight_damped) continue;
      undamped.push_back(state);
      if (!log) continue;
      if (!(d < 0))
        log("warning: " + state + "' has no damping: d(" + state + "')/d" + state + " averages " +
            FormatNumber(d) + " 1/s on the training data, so a free run can drift or diverge");
      else
        log("warning: " + state + "' has no damping running straight: d(" + state + "')/d" + state +
            " is " + FormatNumber(at->second) +
            " 1/s with the lateral motions and the rudder at zero, so a free run can drift or "
            "diverge there");
    }
    model["self_damping"] = damping;
    model["self_damping_straight_running"] = straight;
    model["undamped"] = undamped;
  }
  return model;
}

nlohmann::json Identify(Dataset data, const IdentifyRequest& request, const Logger& log) {
  return Identify(FindMethod(request.method), std::move(data), request, log);
}

}  // namespace usvid
