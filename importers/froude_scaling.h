// Froude scaling of a log between model and full scale (ITTC 7.5-02-06-01, the law of similitude
// behind every free-running model test): at the same Froude number U / sqrt(g L), a length
// scales by lambda = L_full / L_model, a time and a speed by sqrt(lambda), a rate of turn and a
// propeller's revolutions by 1 / sqrt(lambda), a force by lambda^3 and a moment by lambda^4 (the
// same water density on both scales). Angles and accelerations keep their values. lambda > 1
// takes a model-scale log to full scale, lambda < 1 back. Viscous (Reynolds) effects do not
// scale: docs/data.md#froude-scaling says what that leaves.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "core/dataset.h"

namespace usvid {

enum class Dimension {
  kLength,
  kSpeed,
  kRate,
  kRevolutions,
  kAngle,
  kAcceleration,
  kForce,
  kMoment
};

// "length", "speed", "rate", "revolutions", "angle", "acceleration", "force", "moment"; throws
// InputError for another name.
Dimension ParseDimension(const std::string& name);
std::string DimensionName(Dimension d);

// The dimension of a channel named by the data contract (docs/data.md): north, east, x, y are
// lengths; u, v, U, vn, ve and wind speeds are speeds; r (and roll rate p) a rate; n, rev, rpm
// revolutions; psi, delta, chi, nozzle, wind directions (and roll phi) angles; tau_x, tau_y (and
// a propeller's thrust) forces, tau_n (and torque) moments: the importers' extra channels scale
// too. `given` comes first. Throws InputError naming a channel of no known dimension.
Dimension DimensionOf(const std::string& channel, const std::map<std::string, Dimension>& given);

// What was done to one channel, for the report: "u x1.732 (speed)". A derivative channel
// "<name>_dot" is its channel's dimension per second.
struct ScaledChannel {
  std::string channel;
  std::string dimension;
  double factor;
};

// Scales time and every channel of `data` by lambda (> 0, else InputError).
std::vector<ScaledChannel> FroudeScale(Dataset& data, double lambda,
                                       const std::map<std::string, Dimension>& given = {});

}  // namespace usvid
