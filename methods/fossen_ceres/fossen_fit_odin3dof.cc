// The fossen-ceres fits (typed_fossen_fit.h) of Odin3DofModel: the odin3dof model on measured forces.
#include "methods/fossen_ceres/typed_fossen_fit.h"

namespace usvid::fossen {

USVID_FOSSEN_MODEL(Odin3DofModel)

}  // namespace usvid::fossen
