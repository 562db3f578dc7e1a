#include <array>
#include <memory>

#include "core/error.h"
#include "diagnosis/effect_fitter.h"
#include "simulators/vessel_types.h"

namespace usvid::diagnosis {

const EffectFitter& FindEffectFitter(const std::string& vessel) {
  static const auto fitter = [] {
    std::array<std::unique_ptr<const EffectFitter>, kVesselTypeCount> all;
    [&]<std::size_t... I>(std::index_sequence<I...>) {
      ((all[I] = NewEffectFitter<VesselTypeAt<I>>()), ...);
    }(std::make_index_sequence<kVesselTypeCount>{});
    return all;
  }();
  for (const auto& f : fitter)
    if (f->Name() == vessel) return *f;
  throw InputError("diagnose: no effect fitter for vessel '" + vessel + "'");
}

}  // namespace usvid::diagnosis
