// First-order (wave-frequency) motion added to a simulated record, by linear superposition on
// the low-frequency motion the simulator computes (Fossen 2011, Handbook of Marine Craft
// Hydrodynamics and Motion Control, section 10.2: the measured motion is the sum of both). The
// simulator and any maneuver closed on its heading see only the low-frequency motion, as an
// autopilot behind a wave filter does; the sensors see the sum (docs/data.md#waves).
//   sea        long-crested, from `from_rad` (clockwise from north), the ITTC (modified
//              Pierson-Moskowitz) spectrum of significant height Hs and peak period Tp,
//              S(w) = 5/16 Hs^2 wp^4 / w^5 exp(-5/4 (wp / w)^4), wp = 2 pi / Tp, in kComponents
//              random-phase components between 0.6 wp and 3 wp (deep water, k = w^2 / g)
//   phase      p_k = w_k t - k_k (x . d) + phi_k at the vessel's low-frequency position x, so
//              that the motion is seen at the encounter frequency; d: where the waves go
//   surge/sway the vessel follows the water particles (a hull short against the waves):
//              displacement sum a_k sin(p_k) along d; its velocity is the displacement's rate
//              as the vessel sees it, sum a_k w_e,k cos(p_k), at the encounter frequency
//              w_e,k = dp_k/dt = w_k - k_k (U . d) of the low-frequency velocity U; added to
//              the velocity over ground and turned into the body axes of the summed heading, so
//              that the logged velocities integrate to the logged positions
//   yaw        half the wave slope times sin(2 beta), beta the waves' direction off the bow:
//              none in head, following and beam seas, most in quartering seas; its rate at the
//              encounter frequency likewise
//   hull       a hull of length L averages each wave over its length: every component's
//              motion is scaled by |sin(x) / x|, x = k L / 2, so that waves shorter than the
//              hull hardly move it
// The yaw rule gives the order and sign of a slender hull's yaw in oblique waves, not any hull's
// response amplitude operator. Channels U and chi, when present, are computed anew from the
// summed u, v and psi.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "core/dataset.h"

namespace usvid {

struct WaveSea {
  double hs = 0.0;        // [m] significant wave height
  double tp = 0.0;        // [s] peak period
  double from_rad = 0.0;  // where the waves come from, clockwise from north
};

inline constexpr int kWaveComponents = 40;

// "HS[:TP[:FROM_DEG]]": without TP, the fully developed Pierson-Moskowitz sea's Tp = 5.0 sqrt(Hs)
// (at least 2 s); without a direction, one drawn from the seed. InputError naming `where`
// (e.g. "--waves '2:5'") for a height outside (0, 15] m or a period outside [1, 25] s.
WaveSea ParseWaveSea(const std::string& spec, uint64_t seed, const std::string& where);

// Adds the sea's first-order motion to north, east, psi, u, v and r (and recomputes U and chi
// when present); InputError when the record lacks one of the six. Deterministic in the seed.
void AddWaveMotion(Dataset& data, const WaveSea& sea, double hull_length_m, uint64_t seed);

// The hull length for a vessel's waves: its own, else kDefaultHullLengthM (a small craft).
inline constexpr double kDefaultHullLengthM = 10.0;
inline double WaveHullLength(double vessel_length_m) {
  return vessel_length_m > 0 ? vessel_length_m : kDefaultHullLengthM;
}

nlohmann::json WaveSeaToJson(const WaveSea& sea, double hull_length_m);

}  // namespace usvid
