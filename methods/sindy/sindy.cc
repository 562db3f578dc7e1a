#include "methods/sindy/sindy.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/expression.h"
#include "core/parse_number.h"
#include "core/stretches.h"
#include "methods/sindy/weak_form.h"
#include "preprocessing/splits.h"

namespace usvid::sindy {
namespace {

// Normal equations of the problem on unit-RMS columns and target over a set of rows:
// gram = A'A / n, aty = A'y / n with A = columns / scale, y = target / target_scale.
struct ScaledProblem {
  Eigen::MatrixXd gram;
  Eigen::VectorXd aty;
  Eigen::VectorXd scale;
  double target_scale = 1.0;
};

double UnitOr(double rms) { return rms > 0 ? rms : 1.0; }

ScaledProblem MakeProblem(const Eigen::MatrixXd& columns, const Eigen::VectorXd& target,
                          const std::vector<RowRange>& rows) {
  const Eigen::Index p = columns.cols();
  Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(p, p);
  Eigen::VectorXd xty = Eigen::VectorXd::Zero(p);
  double yty = 0.0;
  Eigen::Index n = 0;
  for (const auto& [begin, end] : rows) {
    const auto x = columns.middleRows(begin, end - begin);
    const auto y = target.segment(begin, end - begin);
    gram.selfadjointView<Eigen::Lower>().rankUpdate(x.transpose());
    xty += x.transpose() * y;
    yty += y.squaredNorm();
    n += end - begin;
  }
  const Eigen::MatrixXd full = gram.selfadjointView<Eigen::Lower>();
  ScaledProblem out;
  const auto rows_used = static_cast<double>(n);
  out.scale =
      full.diagonal().unaryExpr([rows_used](double s) { return UnitOr(std::sqrt(s / rows_used)); });
  out.target_scale = UnitOr(std::sqrt(yty / rows_used));
  const Eigen::VectorXd inv = out.scale.cwiseInverse();
  out.gram = inv.asDiagonal() * full * inv.asDiagonal() / rows_used;
  out.aty = inv.cwiseProduct(xty) / (rows_used * out.target_scale);
  return out;
}

// Ridge solution on the active columns (normalised units; zero elsewhere).
Eigen::VectorXd RidgeOn(const ScaledProblem& p, const std::vector<Eigen::Index>& active,
                        double ridge) {
  const auto k = static_cast<Eigen::Index>(active.size());
  Eigen::MatrixXd m(k, k);
  Eigen::VectorXd b(k);
  for (Eigen::Index i = 0; i < k; ++i) {
    b(i) = p.aty(active[i]);
    for (Eigen::Index j = 0; j < k; ++j) m(i, j) = p.gram(active[i], active[j]);
    m(i, i) += ridge * p.gram(active[i], active[i]);
  }
  const Eigen::VectorXd sub = m.completeOrthogonalDecomposition().solve(b);
  Eigen::VectorXd w = Eigen::VectorXd::Zero(p.gram.rows());
  for (Eigen::Index i = 0; i < k; ++i) w(active[i]) = sub(i);
  return w;
}

// STRidge in normalised units, returned in the columns' own units.
Eigen::VectorXd Solve(const ScaledProblem& p, double threshold, double ridge, int max_iterations) {
  std::vector<Eigen::Index> active(static_cast<size_t>(p.gram.rows()));
  for (size_t j = 0; j < active.size(); ++j) active[j] = static_cast<Eigen::Index>(j);
  Eigen::VectorXd w = RidgeOn(p, active, ridge);
  for (int it = 0; it < max_iterations && !active.empty(); ++it) {
    std::vector<Eigen::Index> kept;
    for (Eigen::Index j : active)
      if (std::abs(w(j)) >= threshold) kept.push_back(j);
    if (kept.size() == active.size()) break;
    active = std::move(kept);
    w = active.empty() ? Eigen::VectorXd::Zero(w.size()) : RidgeOn(p, active, ridge);
  }
  if (!active.empty()) w = RidgeOn(p, active, 0.0);
  return (w * p.target_scale).cwiseQuotient(p.scale);
}

std::vector<NamedSignal> Signals(const Dataset& data, const std::vector<std::string>& names) {
  std::vector<NamedSignal> out;
  for (const std::string& n : names) out.push_back({n, data[n]});
  return out;
}

void CheckOptions(const SindyOptions& o) {
  if (o.folds < 2)
    throw InputError("sindy: folds must be at least 2, not " + std::to_string(o.folds));
  if (o.max_iterations < 1)
    throw InputError("sindy: max_iterations must be at least 1, not " +
                     std::to_string(o.max_iterations));
  if (!(std::isfinite(o.ridge) && o.ridge >= 0))
    throw InputError("sindy: ridge must be finite and >= 0, not " + FormatNumber(o.ridge));
  if (!(std::isfinite(o.weak_window_s) && o.weak_window_s >= 0))
    throw InputError("sindy: the weak-form window must be finite and >= 0 s, not " +
                     FormatNumber(o.weak_window_s));
  for (double t : o.thresholds)
    if (!(std::isfinite(t) && t >= 0))
      throw InputError("sindy: a threshold must be finite and >= 0, not " + FormatNumber(t));
}

void CheckChannel(const Dataset& data, const std::string& name) {
  if (!data.Has(name)) {
    data.CheckNotText(name);
    throw InputError("sindy: no channel '" + name + "' in the prepared data");
  }
  if (!data[name].allFinite())
    throw InputError("sindy: channel '" + name + "' has missing or non-finite values");
}

}  // namespace

std::vector<double> DefaultThresholds() {
  std::vector<double> out;
  for (int k = 0; k <= 20; ++k) out.push_back(std::pow(10.0, -4.0 + k / 5.0));
  return out;
}

Eigen::VectorXd StRidge(const Eigen::MatrixXd& columns, const Eigen::VectorXd& target,
                        double threshold, double ridge, int max_iterations) {
  return Solve(MakeProblem(columns, target, {{0, columns.rows()}}), threshold, ridge,
               max_iterations);
}

namespace {

// The stretches of the grid between its gaps, as row ranges.
std::vector<RowRange> GridStretches(const Eigen::VectorXd& t) {
  std::vector<RowRange> pieces;
  for (const Stretch& s : Stretches(t, kGridGapFactor)) pieces.emplace_back(s.first, s.end);
  return pieces;
}

// The candidate thresholds: the options', or the default grid; sorted, each once.
std::vector<double> CandidateThresholds(const SindyOptions& options) {
  std::vector<double> thresholds =
      options.thresholds.empty() ? DefaultThresholds() : options.thresholds;
  std::sort(thresholds.begin(), thresholds.end());
  thresholds.erase(std::unique(thresholds.begin(), thresholds.end()), thresholds.end());
  return thresholds;
}

// The mean held-out MSE over the folds and its standard error, per threshold, and the path
// model.json gives (each threshold's scores and the terms it keeps on all rows).
struct ThresholdPath {
  std::vector<double> mean, se;
  nlohmann::json rows = nlohmann::json::array();
};

template <typename Fit>
ThresholdPath ScoreThresholds(const Eigen::MatrixXd& columns, const Eigen::VectorXd& y,
                              const std::vector<Fold>& folds, const std::vector<double>& thresholds,
                              const Fit& fit) {
  std::vector<ScaledProblem> train;
  for (const Fold& f : folds) train.push_back(MakeProblem(columns, y, f.train));
  const ScaledProblem all = MakeProblem(columns, y, {{0, columns.rows()}});
  const auto k = static_cast<double>(folds.size());
  ThresholdPath p;
  p.mean.resize(thresholds.size());
  p.se.resize(thresholds.size());
  for (size_t t = 0; t < thresholds.size(); ++t) {
    Eigen::VectorXd mse(static_cast<Eigen::Index>(folds.size()));
    for (size_t f = 0; f < folds.size(); ++f) {
      const Eigen::VectorXd w = fit(train[f], thresholds[t]);
      double sse = 0.0;
      Eigen::Index held = 0;
      for (const auto& [begin, end] : folds[f].held_out) {
        sse += (y.segment(begin, end - begin) - columns.middleRows(begin, end - begin) * w)
                   .squaredNorm();
        held += end - begin;
      }
      mse(static_cast<Eigen::Index>(f)) = sse / static_cast<double>(held);
    }
    p.mean[t] = mse.mean();
    p.se[t] = std::sqrt((mse.array() - p.mean[t]).square().sum() / (k - 1) / k);
    p.rows.push_back({{"threshold", thresholds[t]},
                      {"heldout_mse", p.mean[t]},
                      {"heldout_se", p.se[t]},
                      {"terms", (fit(all, thresholds[t]).array() != 0.0).count()}});
  }
  return p;
}

}  // namespace

SindyIdentification IdentifyWithSindy(const PreparedData& prepared,
                                      const std::vector<std::string>& states,
                                      const std::vector<std::string>& variables,
                                      const std::vector<std::string>& inputs,
                                      const SindyOptions& options) {
  CheckOptions(options);
  if (states.empty()) throw InputError("sindy: no states to identify");
  const Dataset& data = prepared.data;
  for (const auto& names : {variables, inputs})
    for (const std::string& n : names) CheckChannel(data, n);
  for (const std::string& s : states) CheckChannel(data, s + "_dot");
  const RegressorLibrary lib =
      BuildLibrary(Signals(data, variables), Signals(data, inputs), options.library);
  if (lib.names.empty()) throw InputError("sindy: the candidate library is empty");

  // The rows regressed: the grid's, or one per weak-form window (methods/sindy/weak_form.h).
  const bool weak = options.weak_window_s > 0;
  WeakWindows windows;
  if (weak) {
    windows = MakeWeakWindows(data.t(), WeakWindowRows(data.t(), options.weak_window_s));
  }
  const Eigen::MatrixXd weak_columns = weak ? WeakColumns(windows, lib.columns) : Eigen::MatrixXd();
  const Eigen::MatrixXd& columns = weak ? weak_columns : lib.columns;
  const Eigen::Index rows = columns.rows();
  if (rows < 10L * options.folds)
    throw InputError("sindy: " + std::to_string(rows) + (weak ? " weak-form windows" : " rows") +
                     " are too few for " + std::to_string(options.folds) +
                     " folds (at least 10 a fold)");

  const std::vector<double> thresholds = CandidateThresholds(options);
  // Each record (or stretch between gaps) is cut into the folds' blocks, so every fold holds
  // out a share of every maneuver.
  const std::vector<Fold> folds =
      BlockFolds(weak ? windows.stretches : GridStretches(data.t()), options.folds);
  const auto fit = [&](const ScaledProblem& p, double threshold) {
    return Solve(p, threshold, options.ridge, options.max_iterations);
  };

  SindyIdentification out;
  for (const std::string& state : states) {
    // The derivative, or its weak counterpart from the raw (unsmoothed) state.
    Eigen::VectorXd weak_y;
    if (weak) {
      const std::string raw = state + "_raw";
      weak_y = WeakTarget(windows, data.Has(raw) ? data[raw] : data[state]);
    }
    const Eigen::VectorXd& y = weak ? weak_y : data[state + "_dot"];
    const ThresholdPath path = ScoreThresholds(columns, y, folds, thresholds, fit);
    const std::vector<double>&mean = path.mean, &se = path.se;
    const size_t best =
        static_cast<size_t>(std::min_element(mean.begin(), mean.end()) - mean.begin());
    size_t chosen = best;
    for (size_t t = best; t < thresholds.size() && options.one_standard_error; ++t)
      if (mean[t] <= mean[best] + se[best]) chosen = t;

    const Eigen::VectorXd w = fit(MakeProblem(columns, y, {{0, rows}}), thresholds[chosen]);
    nlohmann::json terms = nlohmann::json::array();
    for (Eigen::Index j = 0; j < w.size(); ++j) {
      if (w(j) == 0.0) continue;
      const std::string& name = lib.names[static_cast<size_t>(j)];
      out.parameters[state + "." + name] = w(j);
      terms.push_back(name);
    }
    out.equations[state] = WeightedSumText(lib.names, w);
    const double ssr = (y - columns * w).squaredNorm();
    const double sst = (y.array() - y.mean()).square().sum();
    out.details[state] = {{"threshold", thresholds[chosen]},
                          {"min_error_threshold", thresholds[best]},
                          {"heldout_mse", mean[chosen]},
                          {"heldout_se", se[chosen]},
                          {"folds", options.folds},
                          {"thresholds", path.rows},
                          {"terms", terms},
                          {"library", lib.names},
                          {"r2_train", sst > 0 ? 1.0 - ssr / sst : 0.0},
                          {"form", weak ? "weak" : "derivative"}};
    if (weak) {
      out.details[state]["weak_window_s"] = options.weak_window_s;
      out.details[state]["weak_windows"] = rows;
    }
  }
  return out;
}

Eigen::VectorXd PredictWithSindy(const SindyIdentification& id, const std::string& state,
                                 const Dataset& data, const std::vector<std::string>& variables,
                                 const std::vector<std::string>& inputs,
                                 const LibraryOptions& library) {
  const RegressorLibrary lib =
      BuildLibrary(Signals(data, variables), Signals(data, inputs), library);
  Eigen::VectorXd out = Eigen::VectorXd::Zero(data.rows());
  for (size_t j = 0; j < lib.names.size(); ++j) {
    const auto it = id.parameters.find(state + "." + lib.names[j]);
    if (it != id.parameters.end())
      out += it->get<double>() * lib.columns.col(static_cast<Eigen::Index>(j));
  }
  return out;
}

}  // namespace usvid::sindy
