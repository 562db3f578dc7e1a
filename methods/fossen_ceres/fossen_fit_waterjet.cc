// The fossen-ceres fits (typed_fossen_fit.h) of WaterjetModel: the waterjet input map.
#include "methods/fossen_ceres/typed_fossen_fit.h"

namespace usvid::fossen {

USVID_FOSSEN_MODEL(WaterjetModel)

}  // namespace usvid::fossen
