#include "design/method_problem.h"

#include "core/error.h"
#include "methods/eb_lr/eb_lr.h"
#include "methods/identify.h"
#include "simulation/vessel_simulator.h"

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

MethodProblem MethodProblemOf(const std::string& vessel, const std::string& method) {
  const VesselInfo& info = FindVessel(vessel).Info();  // throws for an unknown vessel
  MethodProblem p;
  if (method == "refit") return p;
  if (method == "fossen-ceres" || method == "eb-lr") {
    const std::string own = method == "fossen-ceres" ? "odin3dof" : "eb2dof";
    if (vessel != own)
      throw InputError("design: " + method + " is designed for " + own +
                       " only (its model is that vessel's), not " + vessel);
    p.refit.free = info.params;  // all of them
    p.refit.prior_sd = 1e9;      // none
    if (method == "fossen-ceres") p.refit.segment_s = 10.0;  // fossen-ceres' shooting segments
    p.names = method == "eb-lr" ? EbLrNames() : info.params;
    if (p.names.size() != info.params.size())
      throw std::logic_error("design: eb-lr's default basis is not eb2dof's form");
    return p;
  }
  if (method == "gp" || method == "sindy")
    throw InputError("design: --method " + method +
                     " has no parameters to design a maneuver for (use refit, fossen-ceres or "
                     "eb-lr)");
  throw InputError("design: --method '" + method +
                   "' is not supported (known: refit, fossen-ceres, eb-lr)");
}

Probe ProbeFit(const std::string& vessel, const std::string& method, const Dataset& data) {
  Probe probe;
  if (method != "eb-lr") return probe;
  IdentifyRequest r;
  r.method = method;
  r.vessel = vessel;
  r.threads = 1;
  try {
    probe.model = Identify(data, r);
  } catch (const InputError& e) {
    probe.unusable = e.what();
  }
  return probe;
}

}  // namespace usvid::design
