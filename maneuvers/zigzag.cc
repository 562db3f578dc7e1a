#include "maneuvers/zigzag.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.h"
#include "maneuvers/excitation.h"

namespace usvid {

constexpr double kDeg = std::numbers::pi / 180.0;

ZigZag::ZigZag(const Actuation& act, double rudder_deg, double heading_deg, double duration_s,
               double base_offset_rad)
    : act_(act),
      rudder_deg_(rudder_deg),
      heading_deg_(heading_deg),
      duration_s_(duration_s),
      base_offset_(base_offset_rad) {
  if (act.heading_state < 0) throw InputError("--maneuver zigzag: the vessel has no heading");
  if (!(rudder_deg != 0 && std::isfinite(rudder_deg) && heading_deg > 0))
    throw InputError(
        "--maneuver zigzag:A/B: A must be non-zero degrees (negative: to port first) and B "
        "positive");
  if (rudder_deg < 0) {
    sign_ = first_sign_ = -1;
    rudder_deg_ = -rudder_deg;
  }
}

std::string ZigZag::Spec() const {
  return "zigzag:" + std::string(first_sign_ < 0 ? "-" : "") +
         std::to_string(static_cast<int>(rudder_deg_)) + "/" +
         std::to_string(static_cast<int>(heading_deg_));
}

std::vector<double> ZigZag::InitialCommand() const { return CruiseCommand(act_); }

void ZigZag::Command(double t, std::span<const double> state, std::span<double> u) {
  const std::vector<double> cruise = CruiseCommand(act_);
  std::copy(cruise.begin(), cruise.end(), u.begin());
  if (t < kLeadInS) {
    u[act_.yaw_input] = yaw_.Rest(act_, t);
    return;
  }
  const double psi = state[act_.heading_state];
  if (!started_) {
    psi0_ = psi + base_offset_;
    started_ = true;
  }
  const double heading = psi - psi0_;
  const double threshold = heading_deg_ * kDeg;
  // The excursion beyond the threshold in the direction of the last switch.
  if (!switch_times_.empty()) {
    const double beyond = -sign_ * heading - threshold;
    overshoot_.back() = std::max(overshoot_.back(), beyond);
  }
  if (sign_ * heading >= threshold) {
    sign_ = -sign_;
    switch_times_.push_back(t);
    overshoot_.push_back(0.0);
  }
  u[act_.yaw_input] = yaw_.Toward(act_, t, act_.YawCommand(sign_ * rudder_deg_));
}

nlohmann::json ZigZag::Report() const {
  nlohmann::json r = {{"rudder_deg", rudder_deg_},
                      {"heading_deg", heading_deg_},
                      {"switch_times_s", switch_times_}};
  std::vector<double> deg;
  for (double o : overshoot_) deg.push_back(o / kDeg);
  r["overshoot_deg"] = deg;
  if (!deg.empty()) r["first_overshoot_deg"] = deg[0];
  if (deg.size() > 1) r["second_overshoot_deg"] = deg[1];
  return r;
}

}  // namespace usvid
