#include "sensors/wave_motion.h"

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "core/error.h"
#include "core/parse_number.h"

namespace usvid {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kGravity = 9.81;

double Number(const std::string& text, const std::string& where) {
  const ParsedNumber p = ParseNumber(text);
  if (p.status != NumberStatus::kOk) throw InputError(where + DescribeNumberStatus(p.status, text));
  return p.value;
}

struct Component {
  double amplitude, omega, wavenumber, phase;
};

std::vector<Component> Components(const WaveSea& sea, uint64_t seed) {
  std::seed_seq seq{static_cast<uint32_t>(seed), static_cast<uint32_t>(seed >> 32), 0x3A7Eu};
  std::mt19937_64 rng(seq);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double wp = 2 * kPi / sea.tp, lo = 0.6 * wp, hi = 3.0 * wp;
  const double dw = (hi - lo) / kWaveComponents;
  std::vector<Component> out;
  for (int k = 0; k < kWaveComponents; ++k) {
    // A random frequency within each bin: no two records repeat with a common period.
    const double w = lo + (k + unit(rng)) * dw;
    const double s = 5.0 / 16.0 * sea.hs * sea.hs * std::pow(wp, 4) / std::pow(w, 5) *
                     std::exp(-1.25 * std::pow(wp / w, 4));
    out.push_back({std::sqrt(2 * s * dw), w, w * w / kGravity, 2 * kPi * unit(rng)});
  }
  return out;
}

}  // namespace

WaveSea ParseWaveSea(const std::string& spec, uint64_t seed, const std::string& where) {
  const std::string at = where + ": ";
  WaveSea sea;
  const auto first = spec.find(':');
  sea.hs = Number(spec.substr(0, first), at);
  if (!(sea.hs > 0.0 && sea.hs <= 15.0))
    throw InputError(at + "the significant wave height must be in (0, 15] m");
  sea.tp = std::max(2.0, 5.0 * std::sqrt(sea.hs));
  std::optional<double> from_deg;
  if (first != std::string::npos) {
    const auto second = spec.find(':', first + 1);
    sea.tp = Number(spec.substr(first + 1, second - first - 1), at);
    if (!(sea.tp >= 1.0 && sea.tp <= 25.0))
      throw InputError(at + "the peak period must be in [1, 25] s");
    if (second != std::string::npos) from_deg = Number(spec.substr(second + 1), at);
  }
  if (from_deg) {
    sea.from_rad = *from_deg * kPi / 180.0;
  } else {
    std::mt19937_64 rng(seed ^ 0x5EA5ull);
    sea.from_rad = std::uniform_real_distribution<double>(0.0, 2 * kPi)(rng);
  }
  return sea;
}

void AddWaveMotion(Dataset& data, const WaveSea& sea, double hull_length_m, uint64_t seed) {
  for (const char* name : {"north", "east", "psi", "u", "v", "r"})
    if (!data.Has(name))
      throw InputError(std::string("--waves: the record has no channel '") + name +
                       "' (waves move a vessel with positions, heading and body velocities)");
  std::vector<Component> waves = Components(sea, seed);
  // The hull averages each wave over its length: sin(x) / x of half a length in wave phase.
  for (Component& c : waves) {
    const double x = 0.5 * c.wavenumber * hull_length_m;
    c.amplitude *= x > 1e-9 ? std::abs(std::sin(x) / x) : 1.0;
  }
  const double to = sea.from_rad + kPi;  // where the waves go
  const double dn = std::cos(to), de = std::sin(to);
  Eigen::VectorXd north = data["north"], east = data["east"], psi = data["psi"];
  Eigen::VectorXd u = data["u"], v = data["v"], r = data["r"];
  for (Eigen::Index i = 0; i < data.rows(); ++i) {
    const double t = data.t()(i);
    const double along = north(i) * dn + east(i) * de;
    // The waves' direction off the bow, and the low-frequency speed along d.
    const double relative = to - psi(i);
    const double yaw_gain = 0.5 * std::sin(2 * relative);
    const double speed_along = u(i) * std::cos(relative) + v(i) * std::sin(relative);
    double displacement = 0.0, velocity = 0.0, yaw = 0.0, yaw_rate = 0.0;
    for (const Component& c : waves) {
      const double p = c.omega * t - c.wavenumber * along + c.phase;
      const double encounter = c.omega - c.wavenumber * speed_along;  // dp/dt
      const double sin_p = std::sin(p), cos_p = std::cos(p);
      displacement += c.amplitude * sin_p;
      velocity += c.amplitude * encounter * cos_p;
      yaw += c.wavenumber * c.amplitude * sin_p;
      yaw_rate += c.wavenumber * c.amplitude * encounter * cos_p;
    }
    // The velocity over ground, low-frequency plus the displacement's rate along d, in the
    // body axes of the summed heading (a body-fixed sensor turns with the hull).
    const double vn = u(i) * std::cos(psi(i)) - v(i) * std::sin(psi(i)) + velocity * dn;
    const double ve = u(i) * std::sin(psi(i)) + v(i) * std::cos(psi(i)) + velocity * de;
    psi(i) += yaw_gain * yaw;
    r(i) += yaw_gain * yaw_rate;
    u(i) = vn * std::cos(psi(i)) + ve * std::sin(psi(i));
    v(i) = -vn * std::sin(psi(i)) + ve * std::cos(psi(i));
    north(i) += displacement * dn;
    east(i) += displacement * de;
  }
  // The sensors keep their sampling: each channel is rewritten on its own rows.
  auto set = [&](const char* name, const Eigen::VectorXd& values) {
    data.Set(name, values, data.Get(name).sampled());
  };
  if (data.Has("U") && data.Has("chi")) {
    Eigen::VectorXd speed(data.rows()), course(data.rows());
    for (Eigen::Index i = 0; i < data.rows(); ++i) {
      speed(i) = std::hypot(u(i), v(i));
      course(i) = psi(i) + std::atan2(v(i), u(i));
    }
    set("U", speed);
    set("chi", course);
  }
  set("north", north);
  set("east", east);
  set("psi", psi);
  set("u", u);
  set("v", v);
  set("r", r);
}

nlohmann::json WaveSeaToJson(const WaveSea& sea, double hull_length_m) {
  return {{"hs_m", sea.hs},     {"hull_length_m", hull_length_m},
          {"tp_s", sea.tp},     {"from_deg", sea.from_rad * 180.0 / kPi},
          {"spectrum", "ITTC"}, {"components", kWaveComponents}};
}

}  // namespace usvid
