// RK4 steps per second of every vessel in double, on one thread (bench/rk4_steps.h). Goal
// (issue 3 and 10): odin3dof at 1e7 steps/s in double, Jet within 10x of double
// (simulators_jet_bench.cc).
#include "bench/rk4_steps.h"
#include "simulators/eb2dof.h"
#include "simulators/kvlcc2.h"
#include "simulators/msd.h"
#include "simulators/odin3dof.h"
#include "simulators/odin_hs.h"

namespace usvid {
namespace {

using bench::BM_Rk4Steps;

BENCHMARK(BM_Rk4Steps<Msd, double>);
BENCHMARK(BM_Rk4Steps<Odin3Dof, double>);
BENCHMARK(BM_Rk4Steps<Eb2Dof, double>);
BENCHMARK(BM_Rk4Steps<OdinHs, double>);
BENCHMARK(BM_Rk4Steps<Kvlcc2, double>);

}  // namespace
}  // namespace usvid
