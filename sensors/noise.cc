#include "sensors/noise.h"

#include <cmath>
#include <random>

#include "core/error.h"

namespace usvid {
namespace {

// FNV-1a of the name: a stable per-channel salt.
uint64_t NameHash(const std::string& name) {
  uint64_t h = 1469598103934665603ull;
  for (unsigned char c : name) h = (h ^ c) * 1099511628211ull;
  return h;
}

}  // namespace

std::vector<double> AddGaussianNoise(Dataset& data, const std::vector<std::string>& channels,
                                     double level, uint64_t seed) {
  if (!(level >= 0.0) || !std::isfinite(level))
    throw InputError("--noise: the level must be a non-negative fraction");
  std::vector<double> sds;
  for (const std::string& name : channels) {
    const Channel& c = data.Get(name);
    const auto n = static_cast<double>(c.SampleCount());
    const Eigen::ArrayXd v = c.sampled().select(c.values().array(), 0.0);
    const double mean = n > 0 ? v.sum() / n : 0.0;
    const double var = n > 0 ? c.sampled().select((v - mean).square(), 0.0).sum() / n : 0.0;
    const double sd = level * std::sqrt(var);
    sds.push_back(sd);
    if (sd == 0.0) continue;
    const uint64_t h = NameHash(name);
    std::seed_seq seq{static_cast<uint32_t>(seed), static_cast<uint32_t>(seed >> 32),
                      static_cast<uint32_t>(h), static_cast<uint32_t>(h >> 32)};
    std::mt19937_64 rng(seq);
    std::normal_distribution<double> normal(0.0, sd);
    Eigen::VectorXd noisy = c.values();
    for (Eigen::Index i = 0; i < noisy.size(); ++i) noisy(i) += normal(rng);
    data.Set(name, std::move(noisy), c.sampled());
  }
  return sds;
}

}  // namespace usvid
