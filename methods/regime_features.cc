#include "methods/regime_features.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/parse_number.h"

namespace usvid {

std::vector<DerivedVariable> RegimeFeatures(const std::string& spec, double froude_per_speed,
                                            const Dataset& data, int hinges) {
  if (spec == "none") return {};
  if (spec != "froude" && spec != "hinges" && spec != "auto")
    throw InputError("--features '" + spec + "': unknown (known: auto, hinges, froude, none)");
  const bool explicit_spec = spec != "auto";
  const bool speeds = data.Has("u") && data.Has("v");
  if (explicit_spec && !(froude_per_speed > 0))
    throw InputError("--features " + spec +
                     ": the vessel has no hull length (give --vessel odin-hs, or --features none)");
  if (explicit_spec && !speeds)
    throw InputError("--features " + spec + ": the Froude number needs channels u and v");
  if (!(froude_per_speed > 0) || !speeds || data.rows() == 0) return {};
  const double scale = 1.0 / froude_per_speed;  // sqrt(g L) [m/s]
  const Eigen::ArrayXd fn =
      (data["u"].array().square() + data["v"].array().square()).sqrt() / scale;
  const bool crosses = fn.minCoeff() < kDisplacementFroude && fn.maxCoeff() > kDisplacementFroude;
  const bool planes = fn.minCoeff() < kPlaningFroude && fn.maxCoeff() > kPlaningFroude;
  if (spec == "auto" && !crosses && !planes) return {};
  const std::string froude = "sqrt(u*u + v*v)/" + FormatNumber(scale);
  std::vector<DerivedVariable> out = {{"Fn", froude}};
  if (spec == "froude") return out;
  std::vector<double> sorted(fn.begin(), fn.end());
  std::sort(sorted.begin(), sorted.end());
  std::vector<double> knots;
  for (int i = 1; i <= hinges; ++i) {
    const size_t at = i * (sorted.size() - 1) / (hinges + 1);
    const double knot = std::round(100.0 * sorted[at]) / 100.0;
    if (knots.empty() || knot != knots.back()) knots.push_back(knot);
  }
  for (size_t i = 0; i < knots.size(); ++i)
    out.push_back(
        {"Fn_k" + std::to_string(i + 1), "abs(" + froude + " - " + FormatNumber(knots[i]) + ")"});
  return out;
}

OptionSpec RegimeFeaturesOption(int hinges) {
  return ChoiceOption("features", "auto", {"auto", "hinges", "froude", "none"},
                      "regime features among the variables: auto (hinges when the vessel has a "
                      "length and the record crosses a regime boundary), hinges (the Froude "
                      "number Fn and abs(Fn - k) at " +
                          std::to_string(hinges) +
                          " quantiles of the record's Fn), froude (Fn alone), none");
}

}  // namespace usvid

