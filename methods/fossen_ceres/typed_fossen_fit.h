// The fits of fossen_fit.h for any model of fossen_models.h and jet_force_model.h, defined once;
// fossen_fit_<model>.cc instantiates them for one model each, so that the four models' Jet code
// compiles in parallel.
#pragma once

#include <ceres/ceres.h>

#include <chrono>
#include <cmath>

#include "core/check.h"
#include "core/error.h"
#include "core/evenly_spread.h"
#include "core/parse_number.h"
#include "core/stretches.h"
#include "methods/fossen_ceres/fossen_fit.h"
#include "methods/fossen_ceres/fossen_models.h"
#include "methods/fossen_ceres/jet_force_model.h"
#include "methods/fossen_ceres/knot_window_cost.h"
#include "methods/fossen_ceres/shooting_segment.h"
#include "methods/parameter_sd.h"
#include "simulation/input_track.h"
#include "simulation/open_loop.h"
#include "simulators/odin3dof.h"

namespace usvid::fossen {
namespace detail {

inline double Sd(const Eigen::VectorXd& v) {
  const double sd = std::sqrt((v.array() - v.mean()).square().mean());
  return sd > 0 ? sd : 1.0;
}

// What the solver sees of parameter i: p_i / ParamScale(i) (1 unless the model normalises its
// parameters, when they span many decades: Ceres' Jacobi scaling 1 / (1 + |J_i|) does not lift
// a column whose entries are tiny).
template <typename Model>
std::array<double, Model::kParams> ParamScales(const std::array<double, Model::kParams>& start) {
  std::array<double, Model::kParams> s;
  for (int i = 0; i < Model::kParams; ++i)
    s[i] = Model::kNormaliseParams && start[i] != 0.0 ? std::abs(start[i]) : 1.0;
  return s;
}

// One sample's equation error, normalised: M nu' + C(nu) nu + D(nu) nu - tau(in; p) (forces), or
// nu' - M^-1 (tau(in; p) - C(nu) nu - D(nu) nu) (accelerations) when tau is not measured.
template <typename Model>
struct EquationResidual {
  double u, v, r, du, dv, dr;
  std::array<double, Model::kInputs> in;
  std::array<double, 3> scale;
  std::array<double, Model::kParams> param_scale;
  template <typename T>
  bool operator()(const T* theta, T* res) const {
    const std::array<T, Model::kParams> pa = Unscale<Model::kParams>(theta, param_scale);
    const T* p = pa.data();
    T tau[3];
    std::array<T, Model::kInputs> input;
    for (int i = 0; i < Model::kInputs; ++i) input[i] = T(in[i]);
    Model::Forces(p, input.data(), tau);
    T h[3];  // C(nu) nu + D(nu) nu
    Model::Hull(p, T(u), T(v), T(r), input.data(), h);
    const double rate[3] = {du, dv, dr};
    for (int i = 0; i < 3; ++i)
      res[i] = Model::kAccelerationResidual ? (rate[i] - (tau[i] - h[i]) / p[i]) / scale[i]
                                            : (p[i] * rate[i] + h[i] - tau[i]) / scale[i];
    return true;
  }
};

// Equation errors of up to kBatch consecutive samples in one residual block.
template <typename Model>
struct EquationBatch {
  static constexpr Eigen::Index kBatch = 64;
  std::vector<EquationResidual<Model>> samples;
  template <typename T>
  bool operator()(const T* theta, T* res) const {
    for (size_t k = 0; k < samples.size(); ++k) samples[k](theta, res + 3 * k);
    return true;
  }
};

// The model's prior residuals (JetForceModel: the smoothness of its resistance curve).
template <typename Model>
struct PenaltyResidual {
  std::array<double, Model::kParams> param_scale;
  double weight;
  template <typename T>
  bool operator()(const T* theta, T* res) const {
    const std::array<T, Model::kParams> p = Unscale<Model::kParams>(theta, param_scale);
    Model::Penalty(p.data(), res);
    for (int i = 0; i < Model::kPenaltyResiduals; ++i) res[i] *= weight;
    return true;
  }
};

// Adds the penalty, weighted as one sample of the force (or state) normalised by `scale`.
template <typename Model>
void AddPenalty(ceres::Problem& problem, double* p, const std::array<double, Model::kParams>& ps,
                double scale) {
  if constexpr (Model::kPenaltyResiduals > 0)
    problem.AddResidualBlock(
        new ceres::AutoDiffCostFunction<PenaltyResidual<Model>, Model::kPenaltyResiduals,
                                        Model::kParams>(
            new PenaltyResidual<Model>{ps, 1.0 / scale}),
        nullptr, p);
}

// Positive lower bounds, or the model's smallest values (but for signed parameters); the
// scale-fixing parameter (if any) held constant.
template <typename Model>
void Bound(ceres::Problem& problem, double* p, const std::array<double, Model::kParams>& scale) {
  for (int i = 0; i < Model::kParams; ++i)
    if (!Model::Signed(i))
      problem.SetParameterLowerBound(p, i, std::max(1e-6, Model::MinValue(i) / scale[i]));
  if constexpr (Model::kFixedParam >= 0)
    problem.SetManifold(p, new ceres::SubsetManifold(Model::kParams, {Model::kFixedParam}));
}

template <typename Model>
void Solve(ceres::Problem& problem, const FossenOptions& o, double* p,
           const std::array<double, Model::kParams>& scale, BasicFossenFit<Model::kParams>& fit) {
  constexpr int kParams = Model::kParams;
  ceres::Solver::Options so;
  so.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  so.max_num_iterations = o.max_iterations;
  so.num_threads = o.threads;
  so.function_tolerance = std::max(o.function_tolerance, Model::kFunctionTolerance);
  so.parameter_tolerance = Model::kParameterTolerance;
  so.gradient_tolerance = 1e-14;
  ceres::Solver::Summary summary;
  const auto start = std::chrono::steady_clock::now();
  ceres::Solve(so, &problem, &summary);
  fit.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  fit.termination = ceres::TerminationTypeToString(summary.termination_type) + std::string(": ") +
                    summary.message;
  fit.converged = summary.termination_type == ceres::CONVERGENCE;
  fit.initial_cost = summary.initial_cost;
  fit.final_cost = summary.final_cost;
  fit.iterations = static_cast<int>(summary.iterations.size());
  for (int i = 0; i < kParams; ++i) fit.params[i] = p[i] * scale[i];
  // Covariance (J^T J)^-1 s^2 from the Jacobian at the solution with respect to the parameters
  // alone (their tangent space: a held parameter has no column; for multiple shooting it is
  // conditional on the segments' initial states), summed a residual block at a time:
  // ceres::Covariance's sparse QR of the whole problem was the fit's largest cost on long
  // records, and the whole Jacobian as a CRSMatrix (with Ceres' own copy) 70 MB on 100000 rows.
  const int n = problem.ParameterBlockTangentSize(p);
  Eigen::MatrixXd normal = Eigen::MatrixXd::Zero(n, n);
  std::vector<ceres::ResidualBlockId> ids;
  problem.GetResidualBlocksForParameterBlock(p, &ids);
  for (const ceres::ResidualBlockId id : ids) {
    std::vector<double*> blocks;
    problem.GetParameterBlocksForResidualBlock(id, &blocks);
    const int m = problem.GetCostFunctionForResidualBlock(id)->num_residuals();
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> j(m, n);
    std::vector<double*> jacobians(blocks.size(), nullptr);  // only p's (the others held)
    for (size_t b = 0; b < blocks.size(); ++b)
      if (blocks[b] == p) jacobians[b] = j.data();
    double cost = 0.0;
    if (!problem.EvaluateResidualBlock(id, true, &cost, nullptr, jacobians.data())) return;
    normal.noalias() += j.transpose() * j;
  }
  const Eigen::LDLT<Eigen::MatrixXd> ldlt(normal);
  if (ldlt.info() != Eigen::Success || !(ldlt.vectorD().array() > 0).all()) return;
  const Eigen::MatrixXd c = ldlt.solve(Eigen::MatrixXd::Identity(n, n));
  const bool tangent = n == kParams - (Model::kFixedParam >= 0 ? 1 : 0);
  if (!tangent && n != kParams) return;
  for (int i = 0, column = 0; i < kParams; ++i) {
    if (tangent && i == Model::kFixedParam) continue;  // held: no column, sd 0
    // Scaled by the residual variance per degree of freedom (the residuals are normalised).
    fit.sd[i] = i == Model::kFixedParam ? 0.0 : scale[i] * ParameterSd(c(column, column), summary);
    ++column;
  }
  fit.covariance_ok = true;
}

template <typename Model>
void Require(const PreparedData& prepared) {
  std::vector<std::string> channels = {"u",     "v",     "r",     "u_dot", "v_dot",
                                       "r_dot", "u_raw", "v_raw", "r_raw"};
  std::string inputs;
  for (const std::string_view in : Model::kInputNames) {
    channels.emplace_back(in);
    inputs += (inputs.empty() ? "" : ", ") + std::string(in);
  }
  for (const std::string& c : channels)
    if (!prepared.data.Has(c))
      throw InputError("fossen-ceres: the data need channel '" + c + "' (" +
                       std::string(Model::kName) + ": states u, v, r; inputs " + inputs + ")");
}

template <typename Model>
BasicFossenFit<Model::kParams> FitEquationErrorOf(const PreparedData& prepared,
                                                  const FossenOptions& options) {
  constexpr int kParams = Model::kParams;
  Require<Model>(prepared);
  const Dataset& d = prepared.data;
  std::array<double, kParams> start = Model::kStart;
  if (!options.start.empty()) {
    USVID_CHECK(static_cast<int>(options.start.size()) == kParams, "one start per parameter");
    std::copy(options.start.begin(), options.start.end(), start.begin());
  }
  const std::array<double, kParams> param_scale = ParamScales<Model>(start);
  std::array<double, kParams> p;
  for (int i = 0; i < kParams; ++i) p[i] = start[i] / param_scale[i];
  ceres::Problem problem;
  std::array<std::string, Model::kInputs> in;
  for (int i = 0; i < Model::kInputs; ++i) in[i] = std::string(Model::kInputNames[i]);
  std::array<double, 3> scale;
  for (int i = 0; i < 3; ++i) {
    const std::string rate = std::string(Odin3Dof::kStateNames[3 + i]) + "_dot";
    scale[i] = Sd(d[rate]);
    if constexpr (!Model::kAccelerationResidual) {
      // The forces themselves; a force that is never applied (the step grid holds tau_y at 0)
      // has no spread, and its equation is then scaled by its inertial force, the starting mass
      // times the spread of the acceleration. With the 1 N of a constant's Sd, that homogeneous
      // equation outweighed the others 10^4 to 1, and its trivial solution (m11, m22, Yv, Yvv
      // near 0) started the shooting fit where it could not recover (docs/design.md).
      const Eigen::VectorXd& force = d[in[i]];
      scale[i] =
          (force.array() - force.mean()).square().mean() > 0 ? Sd(force) : start[i] * scale[i];
    }
  }
  ceres::LossFunction* loss = options.robust ? new ceres::HuberLoss(1.0) : nullptr;
  // Samples go into residual blocks of kBatch (one block each when the loss is robust: Huber
  // acts on a block's squared norm). Ceres' cost per block, not per residual, made 100k blocks
  // of 3 residuals cost 15 times 10k.
  const Eigen::Index batch = options.robust ? 1 : EquationBatch<Model>::kBatch;
  const long batches = static_cast<long>((d.rows() + batch - 1) / batch);
  long rows = 0;
  for (const long b : EvenlySpread(
           batches, options.max_rows > 0 ? std::max<long>(1, options.max_rows / batch) : 0)) {
    const Eigen::Index first = b * batch;
    auto* functor = new EquationBatch<Model>;
    for (Eigen::Index k = first; k < std::min(d.rows(), first + batch); ++k) {
      std::array<double, Model::kInputs> input;
      for (int i = 0; i < Model::kInputs; ++i) input[i] = d[in[i]](k);
      functor->samples.push_back({d["u"](k), d["v"](k), d["r"](k), d["u_dot"](k), d["v_dot"](k),
                                  d["r_dot"](k), input, scale, param_scale});
    }
    rows += static_cast<long>(functor->samples.size());
    const int residuals = static_cast<int>(3 * functor->samples.size());
    problem.AddResidualBlock(
        new ceres::AutoDiffCostFunction<EquationBatch<Model>, ceres::DYNAMIC, kParams>(functor,
                                                                                       residuals),
        loss, p.data());
  }
  AddPenalty<Model>(problem, p.data(), param_scale, scale[0]);
  // A model linear in its parameters (measured forces, no held parameter) is solved without its
  // bounds, in a couple of steps; the bounds would have Ceres crawl along them for a hundred. The
  // shooting fit that follows starts from the solution moved inside them.
  if constexpr (!Model::kLinearEquationError) Bound<Model>(problem, p.data(), param_scale);
  BasicFossenFit<kParams> fit;
  fit.rows = rows;
  Solve<Model>(problem, options, p.data(), param_scale, fit);
  if constexpr (Model::kLinearEquationError)
    for (int i = 0; i < kParams; ++i)
      if (!Model::Signed(i))
        fit.params[i] = std::max(fit.params[i], std::max(1e-6, Model::MinValue(i)));
  return fit;
}

// Segment boundaries [b_j, b_{j+1}] of segments up to `segment_s` long: consecutive segments
// share their boundary row. A segment ends at a gap longer than `gap` (core/stretches.h), and
// the one across it is not fitted.
inline std::vector<Eigen::Index> SimulationSegmentBounds(const Eigen::VectorXd& t, double segment_s,
                                                         double gap) {
  const auto rows = t.size();
  std::vector<Eigen::Index> bounds = {0};
  while (bounds.back() < rows - 1) {
    Eigen::Index e = bounds.back();
    while (e + 1 < rows && t(e + 1) - t(bounds.back()) <= segment_s && t(e + 1) - t(e) <= gap) ++e;
    bounds.push_back(std::max(e, bounds.back() + 1));
  }
  return bounds;
}

template <typename Model>
BasicFossenFit<Model::kParams> FitSimulationErrorOf(const PreparedData& prepared,
                                                    const std::array<double, Model::kParams>& start,
                                                    const FossenOptions& options) {
  constexpr int kParams = Model::kParams;
  Require<Model>(prepared);
  const Dataset& d = prepared.data;
  if (!(options.segment_s > 0)) throw InputError("fossen-ceres: segment length must be positive");
  InputTrack track(Model::kInputs);
  std::array<std::string, Model::kInputs> in;
  for (int i = 0; i < Model::kInputs; ++i) in[i] = std::string(Model::kInputNames[i]);
  for (Eigen::Index k = 0; k < d.rows(); ++k) {
    std::array<double, Model::kInputs> u;
    for (int i = 0; i < Model::kInputs; ++i) u[i] = d[in[i]](k);
    track.Append(d.t()(k), u);
  }
  const std::array<double, 3> scale = {Sd(d["u_raw"]), Sd(d["v_raw"]), Sd(d["r_raw"])};
  const double gap = GapLimit(d.t(), kGridGapFactor);
  const std::vector<Eigen::Index> bounds = SimulationSegmentBounds(d.t(), options.segment_s, gap);
  const size_t segments = bounds.size() - 1;
  std::vector<std::array<double, 3>> x0(segments + 1);
  for (size_t j = 0; j <= segments; ++j) {
    const Eigen::Index row = std::min<Eigen::Index>(bounds[std::min(j, segments)], d.rows() - 1);
    x0[j] = {d["u"](row), d["v"](row), d["r"](row)};  // smoothed states: good starts
  }
  const std::array<double, kParams> param_scale = ParamScales<Model>(start);
  std::array<double, kParams> p;
  for (int i = 0; i < kParams; ++i) p[i] = start[i] / param_scale[i];
  ceres::Problem problem;
  ceres::LossFunction* loss = options.robust ? new ceres::HuberLoss(1.0) : nullptr;
  // The segments fitted: all, or on a record longer than max_rows a share spread over it.
  const double rows_per_segment =
      static_cast<double>(d.rows()) / static_cast<double>(std::max<size_t>(1, segments));
  std::vector<bool> fitted(segments + 1, false);
  for (const long j : EvenlySpread(
           static_cast<long>(segments),
           options.max_rows > 0
               ? std::max<long>(
                     1, std::lround(static_cast<double>(options.max_rows) / rows_per_segment))
               : 0))
    fitted[static_cast<size_t>(j)] = true;
  for (size_t j = 0; j < segments; ++j)
    if (d.t()(bounds[j + 1]) - d.t()(bounds[j + 1] - 1) > gap) fitted[j] = false;
  long rows = 0;
  for (size_t j = 0; j < segments; ++j) {
    if (!fitted[j]) continue;
    auto* seg = new SegmentResidual<Model>;
    seg->track = &track;
    for (Eigen::Index k = bounds[j]; k <= bounds[j + 1]; ++k) seg->times.push_back(d.t()(k));
    seg->measured.resize(static_cast<Eigen::Index>(seg->times.size()), 3);
    for (Eigen::Index k = bounds[j]; k <= bounds[j + 1]; ++k)
      seg->measured.row(k - bounds[j]) << d["u_raw"](k), d["v_raw"](k), d["r_raw"](k);
    seg->scale = scale;
    seg->continuity = fitted[j + 1] ? options.continuity_weight : 0.0;
    seg->param_scale = param_scale;
    rows += static_cast<long>(seg->times.size()) - 1;
    const int residuals = seg->Residuals();
    // A model with resistance knots: derivatives over the knots the segment reads (a third of
    // the fit's time on odin-hs, the same Jacobian).
    ceres::CostFunction* cost;
    if constexpr (requires(const double* x, const Environment<double>& e) { Model::KnotAt(x, e); })
      cost = new KnotWindowCost<Model, SegmentResidual<Model>>(
          std::unique_ptr<const SegmentResidual<Model>>(seg), residuals);
    else
      cost = new ceres::AutoDiffCostFunction<SegmentResidual<Model>, ceres::DYNAMIC, kParams, 3, 3>(
          seg, residuals);
    problem.AddResidualBlock(cost, loss, p.data(), x0[j].data(), x0[j + 1].data());
    // The end of the record, or a start that is not fitted: no residual of its own.
    if (!fitted[j + 1]) problem.SetParameterBlockConstant(x0[j + 1].data());
  }
  AddPenalty<Model>(problem, p.data(), param_scale, Sd(d[std::string(Model::kInputNames[0])]));
  Bound<Model>(problem, p.data(), param_scale);
  BasicFossenFit<kParams> fit;
  fit.rows = rows;
  Solve<Model>(problem, options, p.data(), param_scale, fit);
  return fit;
}

template <typename Model>
nlohmann::json EquationsOf(const std::array<double, Model::kParams>& p) {
  if constexpr (requires { Model::EquationText(0, p.data()); }) {
    return {{"u", Model::EquationText(0, p.data())},
            {"v", Model::EquationText(1, p.data())},
            {"r", Model::EquationText(2, p.data())}};
  } else {
    // Odin3Dof::Hull in channel names, M nu' = tau - h.
    using P = Odin3Dof;
    auto n = [&](int i) { return FormatNumber(p[i]); };
    const auto f = [&](int i) { return Model::ForceText(i, p.data()); };
    return {{"u", "(" + f(0) + " + " + n(P::kM22) + "*v*r - (" + n(P::kXu) + " + " + n(P::kXuu) +
                      "*abs(u))*u) / " + n(P::kM11)},
            {"v", "(" + f(1) + " - " + n(P::kM11) + "*u*r - (" + n(P::kYv) + " + " + n(P::kYvv) +
                      "*abs(v))*v) / " + n(P::kM22)},
            {"r", "(" + f(2) + " - (" + n(P::kM22) + " - " + n(P::kM11) + ")*u*v - " + n(P::kNv) +
                      "*v - (" + n(P::kNr) + " + " + n(P::kNrr) + "*abs(r))*r) / " + n(P::kM33)}};
  }
}

}  // namespace detail

template <typename Model>
BasicFossenFit<Model::kParams> FitEquationErrorFor(const PreparedData& prepared,
                                                   const FossenOptions& options) {
  return detail::FitEquationErrorOf<Model>(prepared, options);
}

template <typename Model>
BasicFossenFit<Model::kParams> FitSimulationErrorFor(
    const PreparedData& prepared, const std::array<double, Model::kParams>& start,
    const FossenOptions& options) {
  return detail::FitSimulationErrorOf<Model>(prepared, start, options);
}

template <typename Model>
nlohmann::json EquationsFor(const std::array<double, Model::kParams>& params) {
  return detail::EquationsOf<Model>(params);
}

// The fits' explicit instantiation for one model (fossen_fit_<model>.cc).
#define USVID_FOSSEN_MODEL(Model)                                                            \
  template BasicFossenFit<Model::kParams> FitEquationErrorFor<Model>(const PreparedData&,    \
                                                                     const FossenOptions&);  \
  template BasicFossenFit<Model::kParams> FitSimulationErrorFor<Model>(                      \
      const PreparedData&, const std::array<double, Model::kParams>&, const FossenOptions&); \
  template nlohmann::json EquationsFor<Model>(const std::array<double, Model::kParams>&);

}  // namespace usvid::fossen
