#include "methods/refit/refit.h"

#include "core/error.h"
#include "methods/refit/refit_instances.h"
#include "simulators/vessel_types.h"

namespace usvid {
namespace {

// f.template operator()<V>() for the vessel type V named `vessel`. The data must hold every
// dynamic state of the vessel: for odin-hs, the jets' rpm, nozzle angle and bucket position too
// (a simulated record has them; a log without them is refused, naming the column).
template <typename F>
auto WithVessel(const VesselRef& vessel, const std::string& what, F&& f) {
  auto out = WithVesselType(vessel.Info().type, std::forward<F>(f));
  if (!out) throw InputError(what + ": not available for vessel " + vessel.Name());
  return std::move(*out);
}

const VesselInfo& InfoWithParams(const VesselRef& vessel, size_t params, const char* what) {
  const VesselInfo& info = vessel.Info();
  if (params != info.params.size())
    throw InputError(std::string(what) + ": " + std::to_string(params) + " values for vessel " +
                     vessel.Name() + "'s " + std::to_string(info.params.size()) + " parameters");
  return info;
}

}  // namespace

RefitResult RefitVessel(const VesselRef& vessel, const Dataset& data,
                        const std::vector<double>& start, const RefitOptions& options) {
  const VesselInfo& info = InfoWithParams(vessel, start.size(), kRefitMethodName.data());
  return WithVessel(vessel, "--method refit",
                    [&]<Vessel V>() { return refit::RefitTyped<V>(info, data, start, options); });
}

double MeanSquaredError(const RefitResult& fit) {
  return fit.residuals > 0 ? 2.0 * fit.final_cost / fit.residuals : 0.0;
}

std::map<std::string, Eigen::VectorXd> DerivativeResidual(const VesselRef& vessel,
                                                          const Dataset& prepared,
                                                          const std::vector<double>& params) {
  const VesselInfo& info = InfoWithParams(vessel, params.size(), "derivative residual");
  return WithVessel(vessel, "the derivative residual", [&]<Vessel V>() {
    return refit::DerivativeResidualTyped<V>(info, prepared, params);
  });
}

}  // namespace usvid
