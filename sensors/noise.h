// Seeded Gaussian measurement noise. Each channel gets noise of standard deviation
// level x (standard deviation of the clean channel over the run), so `--noise 0.01` is 1 %
// noise on every channel whatever its units. Each channel draws from its own stream, derived
// from the seed and the channel name, so adding a channel does not change the others' noise.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/dataset.h"

namespace usvid {

// Adds noise to the named channels, in place; returns the standard deviation used per channel.
std::vector<double> AddGaussianNoise(Dataset& data, const std::vector<std::string>& channels,
                                     double level, uint64_t seed);

}  // namespace usvid
