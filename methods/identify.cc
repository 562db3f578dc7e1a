#include "methods/identify.h"

#include "core/derived_channels.h"
#include "core/error.h"
#include "methods/registry.h"
#include "preprocessing/waterjet_forces.h"

namespace usvid {
namespace {

// "gp and sindy": the methods that take regime features.
std::string FeatureMethods() {
  std::string names;
  for (const Method& m : Methods())
    if (m.regime_features) names += (names.empty() ? "" : " and ") + m.name;
  return names;
}

}  // namespace

nlohmann::json Identify(Dataset data, const IdentifyRequest& o, const Logger& log) {
  const Method& method = FindMethod(o.method);
  if (!method.regime_features && o.features != "auto")
    throw InputError("--features: only " + FeatureMethods() + " take regime features");
  if (o.fit_mode != "simulation" && o.fit_mode != "equation")
    throw InputError("--fit '" + o.fit_mode + "': unknown (known: simulation, equation)");
  // Speed and course where only body velocities were logged (the 2-DOF models need them).
  AddSpeedAndCourse(data);
  AddForces(data, o.preprocess.forces);
  return method.identify(data, o, log);
}

}  // namespace usvid
