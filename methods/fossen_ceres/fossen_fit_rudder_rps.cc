// The fossen-ceres fits (typed_fossen_fit.h) of RudderRpsModel: a vessel file's rudder and
// propeller (revolutions per second, four quadrants).
#include "methods/fossen_ceres/typed_fossen_fit.h"

namespace usvid::fossen {

USVID_FOSSEN_MODEL(RudderRpsModel)

}  // namespace usvid::fossen
