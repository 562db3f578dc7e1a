#include "preprocessing/waterjet_forces.h"

#include <cmath>

#include "core/error.h"
#include "simulators/odin_hs.h"

namespace usvid {

void AddWaterjetForces(Dataset& data) {
  std::string missing;
  for (const std::string& c : kWaterjetStateChannels)
    if (!data.Has(c)) missing += (missing.empty() ? "" : ", ") + c;
  if (!missing.empty())
    throw InputError(data.SourcePrefix() +
                     "--forces waterjet: needs the jet states rpm, nozzle_angle, "
                     "bucket_position; the data lack " +
                     missing);
  for (const std::string& c : kWaterjetForceChannels)
    if (data.Has(c))
      throw InputError(data.SourcePrefix() + "--forces waterjet: the data already have '" + c +
                       "'");
  const double* p = OdinHs::kDefaultParams.data();
  const Channel& rpm = data.Get("rpm");
  const Channel& nozzle = data.Get("nozzle_angle");
  const Channel& bucket = data.Get("bucket_position");
  const Eigen::Array<bool, Eigen::Dynamic, 1> sampled =
      rpm.sampled && nozzle.sampled && bucket.sampled;
  const Eigen::Index n = data.rows();
  Eigen::VectorXd fx = Eigen::VectorXd::Constant(n, NAN), fy = fx, fn = fx, flow = fx;
  for (Eigen::Index k = 0; k < n; ++k) {
    if (!sampled(k)) continue;
    const double q = p[OdinHs::kJetFlowPerRpm] * rpm.values(k);
    const double v_jet = q / p[OdinHs::kNozzleArea];
    const double momentum = 2.0 * OdinHs::kRho * q * v_jet;
    // The surge thrust at zero inlet speed: the momentum thrust alone.
    fx(k) = OdinHs::SurgeThrust(rpm.values(k), 0.0, bucket.values(k), nozzle.values(k), p);
    fy(k) = -momentum * std::sin(nozzle.values(k));
    fn(k) = OdinHs::kJetX * fy(k);
    flow(k) = 2.0 * q;
  }
  data.Set("tau_x", fx, sampled);
  data.Set("tau_y", fy, sampled);
  data.Set("tau_n", fn, sampled);
  data.Set("jet_flow", flow, sampled);
}

namespace {
void CheckMap(const std::string& map) {
  if (!map.empty() && map != "waterjet")
    throw InputError("--forces '" + map + "': unknown map (known: waterjet)");
}
}  // namespace

void AddForces(Dataset& data, const std::string& map) {
  CheckMap(map);
  if (!map.empty()) AddWaterjetForces(data);
}

std::vector<std::string> ForceChannels(const std::string& map) {
  CheckMap(map);
  if (map.empty()) return {};
  return {kWaterjetForceChannels.begin(), kWaterjetForceChannels.end()};
}

}  // namespace usvid
