#include <array>
#include <memory>

#include "core/error.h"
#include "diagnosis/typed_effect_fitter.h"
#include "simulators/vessel_types.h"

// The fitters are compiled once a vessel, in the generated effect_fitter_instance_*.cc.
#define USVID_EFFECT_FITTER_EXTERN(V) \
  extern template class usvid::diagnosis::TypedEffectFitter<usvid::V>;
USVID_VESSEL_TYPES(USVID_EFFECT_FITTER_EXTERN)
#undef USVID_EFFECT_FITTER_EXTERN

namespace usvid::diagnosis {

const EffectFitter& FindEffectFitter(const std::string& vessel) {
  static const auto fitter = [] {
    std::array<std::unique_ptr<const EffectFitter>, kVesselTypeCount> all;
    [&]<std::size_t... I>(std::index_sequence<I...>) {
      ((all[I] = std::make_unique<const TypedEffectFitter<VesselTypeAt<I>>>()), ...);
    }(std::make_index_sequence<kVesselTypeCount>{});
    return all;
  }();
  for (const auto& f : fitter)
    if (f->Name() == vessel) return *f;
  throw InputError("diagnose: no effect fitter for vessel '" + vessel + "'");
}

}  // namespace usvid::diagnosis
