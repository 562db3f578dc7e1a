#include "methods/regime_features.h"

#include <cmath>

#include "core/error.h"
#include "core/parse_number.h"

namespace usvid {

std::vector<DerivedVariable> RegimeFeatures(const std::string& spec, double froude_per_speed,
                                            const Dataset& data) {
  if (spec == "none") return {};
  if (spec != "froude" && spec != "auto")
    throw InputError("--features '" + spec + "': unknown (known: auto, froude, none)");
  const bool speeds = data.Has("u") && data.Has("v");
  if (spec == "froude" && !(froude_per_speed > 0))
    throw InputError(
        "--features froude: the vessel has no hull length (give --vessel odin-hs, "
        "or --features none)");
  if (spec == "froude" && !speeds)
    throw InputError("--features froude: the Froude number needs channels u and v");
  if (!(froude_per_speed > 0) || !speeds) return {};
  const double scale = 1.0 / froude_per_speed;  // sqrt(g L) [m/s]
  const Eigen::ArrayXd fn =
      (data["u"].array().square() + data["v"].array().square()).sqrt() / scale;
  const bool crosses = fn.minCoeff() < kDisplacementFroude && fn.maxCoeff() > kDisplacementFroude;
  const bool planes = fn.minCoeff() < kPlaningFroude && fn.maxCoeff() > kPlaningFroude;
  if (spec == "auto" && !crosses && !planes) return {};
  return {{"Fn", "sqrt(u*u + v*v)/" + FormatNumber(scale)}};
}

}  // namespace usvid
