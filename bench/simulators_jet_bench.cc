// RK4 steps per second of every vessel in ceres::Jet, with derivatives with respect to all its
// parameters, on one thread (bench/rk4_steps.h). Compiled with the library's Jet flags
// (usvid_jet_sources), as the fits' rollouts are. Goal (issue 3 and 10): within 10x of double.
#include <ceres/jet.h>

#include "bench/rk4_steps.h"
#include "simulators/eb2dof.h"
#include "simulators/kvlcc2.h"
#include "simulators/msd.h"
#include "simulators/odin3dof.h"
#include "simulators/odin_hs.h"

namespace usvid {
namespace {

using bench::BM_Rk4Steps;

BENCHMARK(BM_Rk4Steps<Msd, ceres::Jet<double, Msd::kParams>>);
BENCHMARK(BM_Rk4Steps<Odin3Dof, ceres::Jet<double, Odin3Dof::kParams>>);
BENCHMARK(BM_Rk4Steps<Eb2Dof, ceres::Jet<double, Eb2Dof::kParams>>);
BENCHMARK(BM_Rk4Steps<OdinHs, ceres::Jet<double, OdinHs::kParams>>);
BENCHMARK(BM_Rk4Steps<Kvlcc2, ceres::Jet<double, Kvlcc2::kParams>>);

}  // namespace
}  // namespace usvid
