#include "maneuvers/true_wind.h"

#include <cmath>
#include <numbers>
#include <random>

#include "core/error.h"

namespace usvid {
namespace {

class UnderWind : public Maneuver {
 public:
  UnderWind(std::unique_ptr<Maneuver> inner, const Actuation& act, const TrueWind& wind,
            uint64_t seed)
      : inner_(std::move(inner)), act_(act), wind_(wind), speed_(wind, seed) {
    for (int i = 0; i < act.inputs(); ++i) {
      if (act.input_names[i] == "wind_speed") speed_input_ = i;
      if (act.input_names[i] == "wind_direction") direction_input_ = i;
    }
    if (speed_input_ < 0 || direction_input_ < 0)
      throw InputError(
          "--wind: the vessel has no wind inputs (wind_speed, wind_direction): give "
          "a vessel file with a wind section (docs/model.md#wind)");
    if (act.heading_state < 0 || act.speed_state < 0 || !act.speed_is_surge)
      throw InputError("--wind: the vessel has no heading and surge-sway states");
  }
  std::string Spec() const override { return inner_->Spec(); }
  double Duration() const override { return inner_->Duration(); }
  std::vector<double> InitialCommand() const override {
    std::vector<double> u = inner_->InitialCommand();
    Set(0.0, 0.0, 0.0, 0.0, u);  // at rest, heading north
    return u;
  }
  void Command(double t, std::span<const double> state, std::span<double> u) override {
    inner_->Command(t, state, u);
    Set(t, state[act_.heading_state], state[act_.speed_state], state[act_.speed_state + 1], u);
  }
  bool Done() const override { return inner_->Done(); }
  std::unique_ptr<Maneuver> Clone() const override { return std::make_unique<UnderWind>(*this); }
  nlohmann::json Report() const override {
    nlohmann::json r = inner_->Report();
    r["true_wind"] = {{"speed", wind_.speed},
                      {"from_deg", wind_.from_rad * 180.0 / std::numbers::pi},
                      {"gust", wind_.gust}};
    return r;
  }

 private:
  template <typename U>
  void Set(double t, double psi, double surge, double sway, U& u) const {
    const std::array<double, 2> rel = RelativeWind(speed_(t), wind_.from_rad, psi, surge, sway);
    u[speed_input_] = rel[0];
    u[direction_input_] = rel[1];
  }
  InnerManeuver inner_;
  Actuation act_;
  TrueWind wind_;
  GustySpeed speed_;
  int speed_input_ = -1, direction_input_ = -1;
};

}  // namespace

GustySpeed::GustySpeed(const TrueWind& wind, uint64_t seed) : wind_(wind) {
  std::mt19937_64 rng(seed ^ 0x57196ull);
  std::uniform_real_distribution<double> phase(0.0, 2.0 * std::numbers::pi);
  for (int k = 0; k < kSines; ++k) {
    frequency_[k] = 0.01 * std::pow(20.0, k / (kSines - 1.0));  // 0.01-0.2 Hz
    phase_[k] = phase(rng);
  }
}

double GustySpeed::operator()(double t) const {
  double g = 0.0;
  for (int k = 0; k < kSines; ++k)
    g += std::sin(2.0 * std::numbers::pi * frequency_[k] * t + phase_[k]) / kSines;
  return wind_.speed * (1.0 + wind_.gust * g);
}

std::array<double, 2> RelativeWind(double true_speed, double true_from_rad, double psi, double u,
                                   double v) {
  // The air moves towards from + pi: w = -W [cos from, sin from] (north, east).
  return RelativeWindOf(
      {-true_speed * std::cos(true_from_rad), -true_speed * std::sin(true_from_rad)}, psi, u, v);
}

std::array<double, 2> RelativeWindOf(const std::array<double, 2>& air, double psi, double u,
                                     double v) {
  const double a_u = std::cos(psi) * air[0] + std::sin(psi) * air[1] - u;
  const double a_v = -std::sin(psi) * air[0] + std::cos(psi) * air[1] - v;
  double from = std::atan2(-a_v, -a_u);
  if (from < 0.0) from += 2.0 * std::numbers::pi;
  return {std::hypot(a_u, a_v), from};
}

std::array<double, 2> AirOverGround(double relative_speed, double relative_from_rad, double psi,
                                    double u, double v) {
  // The air over the hull blows towards from + pi; add the hull's own velocity, turn to north-east.
  const double w_u = -relative_speed * std::cos(relative_from_rad) + u;
  const double w_v = -relative_speed * std::sin(relative_from_rad) + v;
  return {std::cos(psi) * w_u - std::sin(psi) * w_v, std::sin(psi) * w_u + std::cos(psi) * w_v};
}

std::unique_ptr<Maneuver> UnderTrueWind(std::unique_ptr<Maneuver> inner, const Actuation& act,
                                        const TrueWind& wind, uint64_t seed) {
  return std::make_unique<UnderWind>(std::move(inner), act, wind, seed);
}

}  // namespace usvid
