// The fossen-ceres fits (typed_fossen_fit.h) of JetForceModel: the high-speed form on the jets' forces.
#include "methods/fossen_ceres/typed_fossen_fit.h"

namespace usvid::fossen {

USVID_FOSSEN_MODEL(JetForceModel)

}  // namespace usvid::fossen
