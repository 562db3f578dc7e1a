#include "design/design_report.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "plot/heat_map.h"

namespace usvid::design {

size_t Best(const DesignStudy& study) {
  std::optional<size_t> best;
  for (size_t i = 0; i < study.maneuvers.size(); ++i)
    if (study.maneuvers[i].unusable.empty() &&
        (!best || study.maneuvers[i].log_det > study.maneuvers[*best].log_det))
      best = i;
  return best.value_or(0);
}

bool AnyUsable(const DesignStudy& study) {
  return std::any_of(study.maneuvers.begin(), study.maneuvers.end(),
                     [](const ManeuverInformation& m) { return m.unusable.empty(); });
}

nlohmann::json DesignJson(const DesignStudy& study) {
  nlohmann::json maneuvers = nlohmann::json::array();
  for (size_t k = 0; k < study.maneuvers.size(); ++k) {
    const ManeuverInformation& m = study.maneuvers[k];
    nlohmann::json sd = nlohmann::json::object(), rel = nlohmann::json::object(),
                   bound = nlohmann::json::object();
    for (size_t i = 0; i < m.names.size(); ++i) {
      sd[m.names[i]] = m.sd[i];
      rel[m.names[i]] = m.relative_sd[i];
      bound[m.names[i]] = m.shooting_sd[i];
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
                        {"optimized", !m.optimized_from.empty()},
                        {"usable", m.unusable.empty()}};
    if (!m.unusable.empty()) j["unusable_because"] = m.unusable;
    // A shooting fit's sd beside the method's own, where the method is not a shooting fit.
    if (m.shooting_sd != m.sd) j["shooting_fit_sd"] = bound;
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
          {"parameters_of_interest", study.focus},
          {"maneuvers", maneuvers},
          {"best", AnyUsable(study) ? study.maneuvers[Best(study)].maneuver : ""}};
}

void WriteDesignFigure(const DesignStudy& study, const std::string& path) {
  const std::vector<std::string>& names = study.maneuvers.front().names;
  std::vector<std::string> columns;
  Eigen::MatrixXd values(static_cast<Eigen::Index>(names.size()),
                         static_cast<Eigen::Index>(study.maneuvers.size()));
  for (size_t k = 0; k < study.maneuvers.size(); ++k) {
    columns.push_back(study.maneuvers[k].maneuver +
                      (study.maneuvers[k].unusable.empty() ? "" : " (unusable)"));
    // A maneuver the method cannot fit has no sd to show: its cells read n/a.
    for (size_t i = 0; i < names.size(); ++i)
      values(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k)) =
          study.maneuvers[k].unusable.empty()
              ? std::log10(std::max(100.0 * study.maneuvers[k].relative_sd[i], 1e-3))
              : std::numeric_limits<double>::quiet_NaN();
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
