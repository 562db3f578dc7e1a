#include "design/method_problem.h"

#include "core/check.h"
#include "core/error.h"
#include "methods/eb_lr/eb_lr.h"
#include "methods/fossen_ceres/fossen_fit.h"
#include "methods/identify.h"
#include "methods/refit/refit.h"
#include "methods/registry.h"
#include "simulation/vessel_simulator.h"
#include "simulators/eb2dof.h"
#include "simulators/odin3dof.h"

namespace usvid::design {
namespace {

// eb-lr's coefficients in eb2dof's parameter order (simulators/eb2dof.h): m_U's, m_r's, then
// sigma_U's and sigma_r's terms, each from eb-lr's default basis.
std::vector<std::string> EbLrNames() {
  const eb_lr::EbLrOptions o;
  std::vector<std::string> names;
  auto add = [&names](const std::string& prefix, const std::vector<eb_lr::Monomial>& basis) {
    for (const eb_lr::Monomial& m : basis) names.push_back(prefix + "." + m.Text("U", "r"));
  };
  add("m_U", o.mass_speed_basis);
  add("m_r", o.mass_rate_basis);
  add("sigma_U", o.sigma_speed_basis);
  add("sigma_r", o.sigma_rate_basis);
  return names;
}

}  // namespace

MethodProblem MethodProblemOf(const VesselRef& vessel, const std::string& method) {
  const VesselInfo& info = vessel.Info();
  MethodProblem p;
  if (method == kRefitMethodName) return p;
  if (method == fossen::kMethodName || method == eb_lr::kMethodName) {
    const std::string own(method == fossen::kMethodName ? Odin3Dof::kName : Eb2Dof::kName);
    if (vessel.Name() != own)
      throw InputError("design: " + method + " is designed for " + own +
                       " only (its model is that vessel's), not " + vessel.Name());
    p.refit.free = info.params;  // all of them
    p.refit.prior_sd = 1e9;      // none
    if (method == fossen::kMethodName) p.refit.segment_s = 10.0;  // its shooting segments
    p.names = method == eb_lr::kMethodName ? EbLrNames() : info.params;
    USVID_CHECK(p.names.size() == info.params.size(), "eb-lr's default basis is eb2dof's form");
    return p;
  }
  const std::string known = std::string(kRefitMethodName) + ", " +
                            std::string(fossen::kMethodName) + ", " +
                            std::string(eb_lr::kMethodName);
  FindMethod(method);  // throws for an unknown method
  throw InputError("design: --method " + method +
                   " has no simulator's parameters to design a maneuver for (use " + known + ")");
}

Probe ProbeFit(const VesselRef& vessel, const std::string& method, const Dataset& data) {
  Probe probe;
  if (method != eb_lr::kMethodName) return probe;
  IdentifyRequest r;
  r.method = method;
  r.vessel = vessel;
  r.threads = 1;
  // The design's parameters are eb2dof's full basis: a record that cannot carry every term is
  // unusable for it, not fitted at a lower order (eb-lr's default "auto").
  r.options = {{"order", "full"}};
  try {
    probe.model = Identify(data, r);
  } catch (const InputError& e) {
    probe.unusable = e.what();
  }
  return probe;
}

}  // namespace usvid::design
