// Every vessel, the same checks (a conformance suite): the templated dynamics agree between
// double and ceres::Jet, their Jet parameter derivatives match central differences, an RK4 step
// does not allocate, and the adaptive integrator agrees with a fine fixed-step one.
#include <ceres/jet.h>
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>
#include <random>

#include "simulators/dormand_prince.h"
#include "simulators/eb2dof.h"
#include "simulators/kvlcc2.h"
#include "simulators/mmg.h"
#include "simulators/msd.h"
#include "simulators/odin3dof.h"
#include "simulators/odin_hs.h"
#include "simulators/rk4.h"

// Counts heap allocations in this test binary, to show the step does none.
static std::atomic<long> g_allocations{0};
void* operator new(std::size_t n) {
  ++g_allocations;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace usvid {
namespace {

template <typename V>
class VesselConformanceTest : public ::testing::Test {
 protected:
  // A state and input away from zero, so every term of the model is active.
  static void Point(std::array<double, V::kStates>& x, std::array<double, V::kInputs>& u) {
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> d(-1.0, 1.0);
    for (int i = 0; i < V::kStates; ++i) x[i] = d(rng);
    for (int i = 0; i < V::kInputs; ++i)
      u[i] = 0.5 * (V::kInputMin[i] + V::kInputMax[i]) +
             0.3 * d(rng) * (V::kInputMax[i] - V::kInputMin[i]);
    if (V::kName != std::string_view("msd")) x[3] += 5.0;  // a forward speed
    // A rate of turn the hull can have: r L / U of order one (a 320 m tanker turns slowly).
    // (A vessel file's kLength names its length parameter, not the length: below.)
    if constexpr (requires { V::kLength; } && !std::is_same_v<V, Mmg>)
      x[V::kRateState] *= std::min(1.0, 20.0 / V::kLength);
    // A vessel file's length is a parameter (its defaults are kvlcc2's).
    if constexpr (std::is_same_v<V, Mmg>)
      x[V::kRateState] *= 20.0 / V::kDefaultParams[Mmg::kLength];
  }
};

using Vessels = ::testing::Types<Msd, Odin3Dof, Eb2Dof, OdinHs, Kvlcc2, Mmg>;
TYPED_TEST_SUITE(VesselConformanceTest, Vessels);

// The value part of a Jet evaluation is the double evaluation, and the Jet's parameter
// derivatives equal central differences of the double evaluation.
TYPED_TEST(VesselConformanceTest, JetDerivativesMatchCentralDifferences) {
  using V = TypeParam;
  using J = ceres::Jet<double, V::kParams>;
  std::array<double, V::kStates> x;
  std::array<double, V::kInputs> u;
  this->Point(x, u);
  const Environment<double> env{0.3, -0.2};
  std::array<double, V::kStates> dx;
  V::template Derivative<double>(x.data(), u.data(), V::kDefaultParams.data(), env, dx.data());

  std::array<J, V::kStates> xj, dxj;
  std::array<J, V::kInputs> uj;
  std::array<J, V::kParams> pj;
  for (int i = 0; i < V::kStates; ++i) xj[i] = J(x[i]);
  for (int i = 0; i < V::kInputs; ++i) uj[i] = J(u[i]);
  for (int i = 0; i < V::kParams; ++i) pj[i] = J(V::kDefaultParams[i], i);
  const Environment<J> envj{J(0.3), J(-0.2)};
  V::template Derivative<J>(xj.data(), uj.data(), pj.data(), envj, dxj.data());

  for (int i = 0; i < V::kStates; ++i) EXPECT_DOUBLE_EQ(dxj[i].a, dx[i]) << V::kStateNames[i];
  for (int j = 0; j < V::kParams; ++j) {
    // A vessel file's particulars are fixed: no derivative flows through them (simulators/mmg.h).
    if constexpr (requires { V::kFixedFrom; }) {
      if (j >= V::kFixedFrom) {
        for (int i = 0; i < V::kStates; ++i) EXPECT_EQ(dxj[i].v[j], 0.0);
        continue;
      }
    }
    const double h = 1e-6 * (V::kDefaultParams[j] != 0.0 ? std::abs(V::kDefaultParams[j]) : 1.0);
    auto plus = V::kDefaultParams, minus = V::kDefaultParams;
    plus[j] += h;
    minus[j] -= h;
    std::array<double, V::kStates> dp, dm;
    V::template Derivative<double>(x.data(), u.data(), plus.data(), env, dp.data());
    V::template Derivative<double>(x.data(), u.data(), minus.data(), env, dm.data());
    for (int i = 0; i < V::kStates; ++i) {
      const double fd = (dp[i] - dm[i]) / (2 * h);
      EXPECT_NEAR(dxj[i].v[j], fd, 1e-6 * std::max(std::abs(fd), 1e-9 / h))
          << V::kStateNames[i] << " / " << V::kParamNames[j];
    }
  }
}

// A fixed-step RK4 step of a vessel allocates nothing (the hot loop of every simulation).
TYPED_TEST(VesselConformanceTest, Rk4StepDoesNotAllocate) {
  using V = TypeParam;
  std::array<double, V::kStates> x0;
  std::array<double, V::kInputs> u;
  this->Point(x0, u);
  StateVector<double, V::kStates> x = Eigen::Map<StateVector<double, V::kStates>>(x0.data());
  const Environment<double> env;
  auto f = [&](const double* xs, double* dx) {
    V::template Derivative<double>(xs, u.data(), V::kDefaultParams.data(), env, dx);
  };
  const long before = g_allocations.load();
  for (int k = 0; k < 1000; ++k) Rk4Step<double, V::kStates>(f, 0.01, x);
  EXPECT_EQ(g_allocations.load() - before, 0);
  EXPECT_TRUE(x.allFinite());
}

// The adaptive Dormand-Prince integrator and RK4 at a fine step agree over 10 s.
TYPED_TEST(VesselConformanceTest, AdaptiveAgreesWithFineRk4) {
  using V = TypeParam;
  std::array<double, V::kStates> x0;
  std::array<double, V::kInputs> u;
  this->Point(x0, u);
  const Environment<double> env;
  auto f = [&](const double* xs, double* dx) {
    V::template Derivative<double>(xs, u.data(), V::kDefaultParams.data(), env, dx);
  };
  StateVector<double, V::kStates> a = Eigen::Map<StateVector<double, V::kStates>>(x0.data());
  StateVector<double, V::kStates> b = a;
  for (int k = 0; k < 10000; ++k) Rk4Step<double, V::kStates>(f, 0.001, a);
  const AdaptiveResult r = DormandPrinceIntegrate<double, V::kStates>(f, 10.0, b);
  ASSERT_TRUE(r.ok);
  EXPECT_LT(r.steps, 5000);
  for (int i = 0; i < V::kStates; ++i)
    EXPECT_NEAR(a(i), b(i), 1e-6 * (1 + std::abs(a(i)))) << V::kStateNames[i];
}

}  // namespace
}  // namespace usvid
