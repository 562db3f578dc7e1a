#include "preprocessing/waterjet_forces.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "simulators/odin_hs.h"

namespace usvid {

std::array<double, 4> WaterjetForces(double rpm, double nozzle_angle, double bucket_position) {
  const double* p = OdinHs::kDefaultParams.data();
  const double q = p[OdinHs::kJetFlowPerRpm] * rpm;
  const double v_jet = q / p[OdinHs::kNozzleArea];
  const double momentum = 2.0 * OdinHs::kRho * q * v_jet;
  // The surge thrust at zero inlet speed: the momentum thrust alone.
  const double fy = -momentum * std::sin(nozzle_angle);
  return {OdinHs::SurgeThrust(rpm, 0.0, bucket_position, nozzle_angle, p), fy, OdinHs::kJetX * fy,
          2.0 * q};
}

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
  const Channel& rpm = data.Get("rpm");
  const Channel& nozzle = data.Get("nozzle_angle");
  const Channel& bucket = data.Get("bucket_position");
  const Eigen::Array<bool, Eigen::Dynamic, 1> sampled =
      rpm.sampled() && nozzle.sampled() && bucket.sampled();
  const Eigen::Index n = data.rows();
  Eigen::VectorXd fx = Eigen::VectorXd::Constant(n, NAN), fy = fx, fn = fx, flow = fx;
  for (Eigen::Index k = 0; k < n; ++k) {
    if (!sampled(k)) continue;
    const auto f = WaterjetForces(rpm.Value(k), nozzle.Value(k), bucket.Value(k));
    fx(k) = f[0], fy(k) = f[1], fn(k) = f[2], flow(k) = f[3];
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

bool HasWaterjetStates(const std::vector<std::string>& channels) {
  return std::ranges::all_of(kWaterjetStateChannels, [&](const std::string& c) {
    return std::ranges::find(channels, c) != channels.end();
  });
}

std::vector<std::string> ForceChannels(const std::string& map) {
  CheckMap(map);
  if (map.empty()) return {};
  return {kWaterjetForceChannels.begin(), kWaterjetForceChannels.end()};
}

}  // namespace usvid
