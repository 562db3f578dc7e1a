// Accuracy and cost of the derivative estimators (issue 4's table): odin3dof random-step data,
// 600 s at 20 Hz, noise 0.1 % to 5 % of each channel's standard deviation. Counters: rms = RMS
// error of u', v', r' over RMS of the true derivative (mean of the three), lag = largest |lag|
// in samples (cross-correlation peak against the truth). The report's pipeline is `euler`.
#include <benchmark/benchmark.h>

#include <map>

#include "maneuvers/maneuver_factory.h"
#include "preprocessing/cross_correlation.h"
#include "preprocessing/derivative.h"
#include "sensors/noise.h"
#include "simulation/vessel_simulator.h"
#include "simulators/odin3dof.h"

namespace usvid {
namespace {

struct Truth {
  Dataset clean;
  Eigen::MatrixXd derivative;  // u', v', r'
  std::vector<Eigen::Index> breaks;
};

Truth MakeTruth(const std::string& maneuver) {
  {
    Truth t;
    const VesselSimulator& sim = FindVessel("odin3dof");
    auto m = MakeManeuver(maneuver, sim.Info().actuation, 600.0, 21);
    t.clean = sim.RunManeuver(*m, sim.Info().default_params, {}, RunOptions{}).data;
    t.derivative.resize(t.clean.rows(), 3);
    for (Eigen::Index k = 0; k < t.clean.rows(); ++k) {
      double x[6], u[3], dx[6];
      int i = 0;
      for (const char* s : {"north", "east", "psi", "u", "v", "r"}) x[i++] = t.clean[s](k);
      i = 0;
      for (const char* s : {"tau_x", "tau_y", "tau_n"}) u[i++] = t.clean[s](k);
      Odin3Dof::Derivative<double>(x, u, Odin3Dof::kDefaultParams.data(), {}, dx);
      t.derivative.row(k) << dx[3], dx[4], dx[5];
    }
    t.breaks = StepBreaks({t.clean["tau_x"], t.clean["tau_y"], t.clean["tau_n"]});
    return t;
  }
}

const Truth& Odin3DofTruth(const std::string& maneuver) {
  static std::map<std::string, Truth> cache;
  if (!cache.count(maneuver)) cache[maneuver] = MakeTruth(maneuver);
  return cache.at(maneuver);
}

void BM_Derivative(benchmark::State& state, const std::string& maneuver, const std::string& spec,
                   bool use_breaks) {
  const Truth& truth = Odin3DofTruth(maneuver);
  const double noise = state.range(0) / 1000.0;
  Dataset noisy = truth.clean;
  AddGaussianNoise(noisy, {"u", "v", "r"}, noise, 77);
  const DerivativeMethod method = DerivativeMethod::Parse(spec);
  const std::vector<Eigen::Index> none;
  double rms = 0.0, lag = 0.0;
  for (auto _ : state) {
    rms = lag = 0.0;
    int c = 0;
    for (const char* name : {"u", "v", "r"}) {
      const Eigen::VectorXd d =
          SmoothAndDifferentiate(noisy[name], 0.05, method, use_breaks ? truth.breaks : none)
              .derivative;
      const Eigen::VectorXd want = truth.derivative.col(c++);
      const double e = std::sqrt((d - want).squaredNorm() / want.squaredNorm());
      state.counters[std::string("rms_") + name] = e;
      rms += e / 3.0;
      lag = std::max(lag, std::abs(EstimateLag(want, d, 20).lag));
    }
  }
  state.counters["noise_percent"] = noise * 100;
  state.counters["rms"] = rms;
  state.counters["lag"] = lag;
}

#define USVID_DERIVATIVE_BENCH(label, spec, breaks)                                                \
  BENCHMARK_CAPTURE(BM_Derivative, steps_##label, std::string("random-steps"), std::string(spec),  \
                    breaks)                                                                        \
      ->Arg(1)                                                                                     \
      ->Arg(5)                                                                                     \
      ->Arg(10)                                                                                    \
      ->Arg(20)                                                                                    \
      ->Arg(50)                                                                                    \
      ->Iterations(1)                                                                              \
      ->Unit(benchmark::kMillisecond);                                                             \
  BENCHMARK_CAPTURE(BM_Derivative, multisine_##label, std::string("multisine"), std::string(spec), \
                    breaks)                                                                        \
      ->Arg(1)                                                                                     \
      ->Arg(5)                                                                                     \
      ->Arg(10)                                                                                    \
      ->Arg(20)                                                                                    \
      ->Arg(50)                                                                                    \
      ->Iterations(1)                                                                              \
      ->Unit(benchmark::kMillisecond)

USVID_DERIVATIVE_BENCH(euler_report, "euler", false);
USVID_DERIVATIVE_BENCH(euler_21, "euler:21", false);
USVID_DERIVATIVE_BENCH(euler_41, "euler:41", false);
USVID_DERIVATIVE_BENCH(sg_21_3, "sg:21:3", false);
USVID_DERIVATIVE_BENCH(sg_11_2, "sg:11:2", false);
USVID_DERIVATIVE_BENCH(tv, "tv", false);
USVID_DERIVATIVE_BENCH(spline, "spline", false);
USVID_DERIVATIVE_BENCH(spline_step_breaks, "spline", true);
USVID_DERIVATIVE_BENCH(sg_21_3_step_breaks, "sg:21:3", true);

}  // namespace
}  // namespace usvid
