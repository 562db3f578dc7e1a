// Which integrator a simulation steps with: fixed-step RK4, or adaptive Dormand-Prince over the
// same span (simulation/plant_stepper.h). Its own header, so that options can name it without
// the integrators' templates.
#pragma once

namespace usvid {

enum class Integrator { kRk4, kDormandPrince };

}  // namespace usvid
