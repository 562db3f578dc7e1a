#include "maneuvers/turning.h"

#include <cmath>
#include <numbers>

#include "core/error.h"
#include "maneuvers/excitation.h"

namespace usvid {

Turning::Turning(const Actuation& act, double rudder_deg, double duration_s)
    : act_(act), rudder_deg_(rudder_deg), duration_s_(duration_s) {
  if (act.heading_state < 0) throw InputError("--maneuver turning: the vessel has no heading");
  if (rudder_deg == 0) throw InputError("--maneuver turning:A: A must not be 0");
}

std::string Turning::Spec() const {
  return "turning:" + std::to_string(static_cast<int>(rudder_deg_));
}

std::vector<double> Turning::InitialCommand() const { return CruiseCommand(act_); }

void Turning::Command(double t, std::span<const double> state, std::span<double> u) {
  const std::vector<double> cruise = CruiseCommand(act_);
  std::copy(cruise.begin(), cruise.end(), u.begin());
  if (t < kLeadInS) {
    u[act_.yaw_input] = yaw_.Rest(act_, t);
    return;
  }
  const double psi = state[act_.heading_state];
  const bool positions = act_.north_state >= 0 && act_.east_state >= 0;
  if (!started_) {
    started_ = true;
    psi0_ = psi;
    if (positions) {
      north0_ = state[act_.north_state];
      east0_ = state[act_.east_state];
    }
  }
  if (positions) {
    // Advance: along the initial heading; transfer: across it, to the turning side.
    const double dn = state[act_.north_state] - north0_, de = state[act_.east_state] - east0_;
    const double along = dn * std::cos(psi0_) + de * std::sin(psi0_);
    const double across = -dn * std::sin(psi0_) + de * std::cos(psi0_);
    const double turned = std::abs(psi - psi0_);
    const double side = rudder_deg_ > 0 ? 1.0 : -1.0;
    if (advance_ < 0 && turned >= std::numbers::pi / 2) {
      advance_ = along;
      transfer_ = side * across;
    }
    if (tactical_ < 0 && turned >= std::numbers::pi) tactical_ = side * across;
  }
  if (act_.speed_state >= 0) {
    const double r = state[act_.rate_state];
    if (std::abs(r) > 1e-6) last_radius_ = act_.Speed(state) / std::abs(r);
  }
  u[act_.yaw_input] = yaw_.Toward(act_, t, act_.YawCommand(rudder_deg_));
}

nlohmann::json Turning::Report() const {
  nlohmann::json r = {{"rudder_deg", rudder_deg_}};
  if (advance_ >= 0) r["advance_m"] = advance_;
  if (transfer_ >= 0 || advance_ >= 0) r["transfer_m"] = transfer_;
  if (tactical_ >= 0) r["tactical_diameter_m"] = tactical_;
  if (last_radius_ >= 0) r["steady_turning_radius_m"] = last_radius_;
  return r;
}

}  // namespace usvid
