#include "methods/refit/refit.h"

#include "core/error.h"
#include "methods/refit/typed_refit.h"
#include "simulators/eb2dof.h"
#include "simulators/kvlcc2.h"
#include "simulators/msd.h"
#include "simulators/odin3dof.h"
#include "simulators/odin_hs.h"

namespace usvid {

RefitResult RefitVessel(const std::string& vessel, const Dataset& data,
                        const std::vector<double>& start, const RefitOptions& options) {
  const VesselInfo& info = FindVessel(vessel).Info();
  if (start.size() != info.params.size())
    throw InputError("refit: " + std::to_string(start.size()) + " starting values for vessel " +
                     vessel + "'s " + std::to_string(info.params.size()) + " parameters");
  if (vessel == "kvlcc2") return refit::RefitTyped<Kvlcc2>(info, data, start, options);
  if (vessel == "odin3dof") return refit::RefitTyped<Odin3Dof>(info, data, start, options);
  if (vessel == "eb2dof") return refit::RefitTyped<Eb2Dof>(info, data, start, options);
  if (vessel == "msd") return refit::RefitTyped<Msd>(info, data, start, options);
  throw InputError("--method refit: not available for vessel " + vessel +
                   " (its actuator states are not measured)");
}

}  // namespace usvid
