// The fossen-ceres fits (typed_fossen_fit.h) of RudderModel: the rudder-propeller input map.
#include "methods/fossen_ceres/typed_fossen_fit.h"

namespace usvid::fossen {

USVID_FOSSEN_MODEL(RudderModel)

}  // namespace usvid::fossen
