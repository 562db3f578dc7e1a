#include "core/error.h"
#include "methods/channel_fit.h"
#include "methods/method.h"
#include "methods/nominal/nominal.h"
#include "simulation/vessel_simulator.h"

namespace usvid {
namespace {

nlohmann::json NominalModel(const Dataset& data, const IdentifyRequest& o, const MethodOptions&,
                            const Logger&) {
  if (o.vessel.empty()) throw InputError("--method nominal: needs --vessel");
  const VesselInfo& info = o.vessel.Info();
  const std::vector<double>& p = o.start_params.empty() ? info.default_params : o.start_params;
  nlohmann::json params = nlohmann::json::object();
  for (size_t i = 0; i < p.size(); ++i) params[info.params[i]] = p[i];
  return {{"method", o.method},
          {"vessel", o.vessel.Name()},
          {"states", VesselVariables(o.vessel)},
          {"inputs", info.inputs},
          {"parameters", params},
          {"train", {{"data", o.data_name}, {"samples", data.rows()}, {"seconds", 0.0}}}};
}

}  // namespace

Method NominalMethod() {
  Method m;
  m.name = std::string(kNominalMethodName);
  m.summary = "the --vessel as it is, a baseline";
  m.identify = NominalModel;
  return m;
}

}  // namespace usvid
