#include "design/design_report.h"

#include <cmath>

#include "plot/heat_map.h"

namespace usvid::design {

size_t Best(const DesignStudy& study) {
  size_t best = 0;
  for (size_t i = 1; i < study.maneuvers.size(); ++i)
    if (study.maneuvers[i].log_det > study.maneuvers[best].log_det) best = i;
  return best;
}

nlohmann::json DesignJson(const DesignStudy& study) {
  nlohmann::json maneuvers = nlohmann::json::array();
  for (size_t k = 0; k < study.maneuvers.size(); ++k) {
    const ManeuverInformation& m = study.maneuvers[k];
    nlohmann::json sd = nlohmann::json::object(), rel = nlohmann::json::object();
    for (size_t i = 0; i < m.names.size(); ++i) {
      sd[m.names[i]] = m.sd[i];
      rel[m.names[i]] = m.relative_sd[i];
    }
    nlohmann::json weakest = nlohmann::json::array();
    for (const WeakDirection& w : m.weakest) {
      nlohmann::json p = nlohmann::json::array();
      for (const auto& [name, weight] : w.parameters)
        if (std::abs(weight) >= 0.1) p.push_back({{"parameter", name}, {"weight", weight}});
      weakest.push_back({{"information", w.eigenvalue},
                         {"relative_sd", w.eigenvalue > 0 ? 1.0 / std::sqrt(w.eigenvalue) : 1e300},
                         {"parameters", p}});
    }
    nlohmann::json j = {{"maneuver", m.maneuver},
                        {"parameter_sd", sd},
                        {"parameter_relative_sd", rel},
                        {"log_det_information", m.log_det},
                        {"trace_inverse_information", m.trace_inverse},
                        {"condition_number", m.condition_number},
                        {"weakest_directions", weakest},
                        {"seconds", m.seconds},
                        {"optimized", !m.optimized_from.empty()}};
    if (!m.optimized_from.empty()) j["optimized_from"] = m.optimized_from;
    if (k < study.checks.size() && study.checks[k]) {
      const SpreadCheck& c = *study.checks[k];
      nlohmann::json observed = nlohmann::json::object(), ratio = nlohmann::json::object();
      for (size_t i = 0; i < c.observed_sd.size(); ++i) {
        observed[m.names[i]] = c.observed_sd[i];
        ratio[m.names[i]] = c.ratio[i];
      }
      j["check"] = {{"runs", c.runs},
                    {"failed", c.failed},
                    {"observed_sd", observed},
                    {"predicted_over_observed", ratio},
                    {"median_ratio", c.median_ratio}};
    }
    maneuvers.push_back(j);
  }
  return {{"vessel", study.vessel},
          {"method", study.method},
          {"noise", study.noise},
          {"duration_s", study.duration_s},
          {"maneuvers", maneuvers},
          {"best", study.maneuvers.empty() ? "" : study.maneuvers[Best(study)].maneuver}};
}

void WriteDesignFigure(const DesignStudy& study, const std::string& path) {
  const std::vector<std::string>& names = study.maneuvers.front().names;
  std::vector<std::string> columns;
  Eigen::MatrixXd values(static_cast<Eigen::Index>(names.size()),
                         static_cast<Eigen::Index>(study.maneuvers.size()));
  for (size_t k = 0; k < study.maneuvers.size(); ++k) {
    columns.push_back(study.maneuvers[k].maneuver);
    for (size_t i = 0; i < names.size(); ++i)
      values(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k)) =
          std::log10(std::max(100.0 * study.maneuvers[k].relative_sd[i], 1e-3));
  }
  HeatMap map(names, columns, values);
  map.SetTitle(study.vessel + ", " + study.method + ": predicted sd of each parameter (" +
               std::to_string(static_cast<int>(study.duration_s)) + " s, noise " +
               std::to_string(study.noise * 100.0).substr(0, 4) + " %)")
      .SetAxisLabels("parameter", "maneuver")
      .SetValueLabel("log10 of the relative sd in %")
      .SetFormatter([](double v) {
        const double pct = std::pow(10.0, v);
        char buf[32];
        std::snprintf(buf, sizeof buf, pct < 10 ? "%.2g%%" : "%.0f%%", pct);
        return std::string(buf);
      });
  const int width = 260 + 110 * static_cast<int>(columns.size());
  const int height = 160 + 34 * static_cast<int>(names.size());
  map.WriteSvg(path, std::max(width, HeatMap::kMinWidth), std::max(height, HeatMap::kMinHeight));
}

}  // namespace usvid::design
