// Data every benchmark area shares, made once per process (simulated, noisy as a sensor would
// give it, with the seed fixed): so that the areas time the same work run after run.
#pragma once

#include <array>
#include <vector>

#include "methods/gp/search.h"
#include "methods/gp/tree.h"
#include "preprocessing/pipeline.h"

namespace usvid::bench {

// odin3dof random steps at 20 Hz, `rows` rows, 0.5 % noise, preprocessed for u, v, r with
// tau_x, tau_y, tau_n (smoothed states, derivatives, raw measurements). 18k rows: 900 s.
const PreparedData& OdinPrepared(long rows = 18000);
// odin-hs random steps at 20 Hz (18k rows), preprocessed for u, v, r with its waterjet inputs.
const PreparedData& OdinHsPrepared();
// odin-hs random steps, 300 s, on the jets' forces (`--forces waterjet`) at 10 Hz: what the
// default compare's fossen-ceres fits on odin-hs (JetForceModel's 60 parameters).
const PreparedData& JetForcesPrepared();
// The same waterjet commands driving fossen-ceres' own waterjet model (its 13 parameters at
// `WaterjetTruth()`), 0.5 % noise, preprocessed: data a 12-parameter fit can match.
const PreparedData& WaterjetModelPrepared();
const std::array<double, 13>& WaterjetTruth();
// r' of odin3dof as a GP problem on `rows` rows (variables u, v, r, tau_x, tau_y, tau_n).
const gp::GpProblem& OdinGpProblem(long rows = 10000);
// 200 random trees of depth up to 6 over + - * abs and 6 variables (Operon's benchmark mix).
const std::vector<gp::Tree>& RandomTrees();

}  // namespace usvid::bench
