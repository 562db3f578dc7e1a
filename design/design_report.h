// What `usvid design` writes: design.json (per maneuver its predicted parameter sd, log det,
// condition number and weakest directions, whether the method can fit it, the check beside it
// when run, and the best usable maneuver by log det) and design.svg (a heat map of the predicted
// relative sd [%], parameters by maneuver; n/a for a maneuver the method cannot fit).
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "design/information.h"
#include "design/spread_check.h"

namespace usvid::design {

struct DesignStudy {
  std::string vessel, method;
  double noise = 0.0, duration_s = 0.0;
  std::vector<std::string> focus;  // parameters of interest; empty: all
  std::vector<ManeuverInformation> maneuvers;
  std::vector<std::optional<SpreadCheck>> checks;  // one per maneuver (none: not checked)
};

// Index of the usable maneuver with the largest log det (the first maneuver when none is usable).
size_t Best(const DesignStudy& study);
bool AnyUsable(const DesignStudy& study);
nlohmann::json DesignJson(const DesignStudy& study);
void WriteDesignFigure(const DesignStudy& study, const std::string& path);

}  // namespace usvid::design
