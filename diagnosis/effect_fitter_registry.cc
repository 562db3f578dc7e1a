#include "core/error.h"
#include "diagnosis/typed_effect_fitter.h"
#include "simulators/eb2dof.h"
#include "simulators/kvlcc2.h"
#include "simulators/msd.h"
#include "simulators/odin3dof.h"
#include "simulators/odin_hs.h"

namespace usvid::diagnosis {

const EffectFitter& FindEffectFitter(const std::string& vessel) {
  static const TypedEffectFitter<Msd> msd;
  static const TypedEffectFitter<Odin3Dof> odin3dof;
  static const TypedEffectFitter<Eb2Dof> eb2dof;
  static const TypedEffectFitter<OdinHs> odin_hs;
  static const TypedEffectFitter<Kvlcc2> kvlcc2;
  for (const EffectFitter* f :
       std::initializer_list<const EffectFitter*>{&msd, &odin3dof, &eb2dof, &odin_hs, &kvlcc2})
    if (f->Name() == vessel) return *f;
  throw InputError("diagnose: no effect fitter for vessel '" + vessel + "'");
}

}  // namespace usvid::diagnosis
