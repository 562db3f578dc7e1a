#include "methods/hybrid/term_proposals.h"

#include <Eigen/QR>

#include "preprocessing/regressor_library.h"

namespace usvid::hybrid {
namespace {

// U^2 f(z) with f of degree two: z the velocity states other than the speed u over u (v' = v/u,
// r' ~ r/u) and the inputs; with U ~ u, the columns u^2 z_i z_j, u^2 |z_i| z_i, u^2 z_i and u^2,
// each written with the powers of u cancelled ("v*r", "u*v*delta", "u*u*delta").
RegressorLibrary SpeedScaledLibrary(const std::vector<NamedSignal>& signals,
                                    const std::vector<std::string>& inputs,
                                    const Eigen::VectorXd& u, const std::string& speed) {
  struct Factor {
    const NamedSignal* signal;
    bool velocity;  // carries 1/u
  };
  std::vector<Factor> z;
  for (const NamedSignal& s : signals) {
    if (s.name == speed) continue;
    const bool input = std::find(inputs.begin(), inputs.end(), s.name) != inputs.end();
    z.push_back({&s, !input});
  }
  RegressorLibrary out;
  std::vector<Eigen::VectorXd> columns;
  // u^(2 - velocity factors) times the factors (abs: |z| z of the one factor given).
  auto add = [&](const std::vector<const Factor*>& factors, bool abs) {
    std::vector<std::string> names;
    Eigen::VectorXd column = Eigen::VectorXd::Ones(u.size());
    int power = 2;
    for (const Factor* f : factors) {
      const int times = abs ? 2 : 1;
      power -= f->velocity ? times : 0;
      column = column.cwiseProduct(abs ? f->signal->values.cwiseAbs().cwiseProduct(f->signal->values)
                                       : f->signal->values);
      names.push_back(abs ? "abs(" + f->signal->name + ")*" + f->signal->name : f->signal->name);
    }
    std::string name;
    for (int k = 0; k < power; ++k) {
      column = column.cwiseProduct(u);
      name += (name.empty() ? "" : "*") + speed;
    }
    for (const std::string& n : names) name += (name.empty() ? "" : "*") + n;
    out.names.push_back(name);
    columns.push_back(std::move(column));
  };
  add({}, false);
  for (const Factor& f : z) add({&f}, false);
  for (size_t i = 0; i < z.size(); ++i) {
    for (size_t k = i; k < z.size(); ++k) add({&z[i], &z[k]}, false);
    add({&z[i]}, true);
  }
  out.columns.resize(u.size(), static_cast<Eigen::Index>(columns.size()));
  for (size_t j = 0; j < columns.size(); ++j) out.columns.col(static_cast<Eigen::Index>(j)) = columns[j];
  return out;
}

}  // namespace

std::vector<TermProposal> ProposeTerms(const Dataset& prepared,
                                       const std::map<std::string, Eigen::VectorXd>& residual,
                                       const std::vector<std::string>& inputs, int per_state,
                                       const std::string& speed) {
  std::vector<NamedSignal> signals;
  for (const auto& [state, _] : residual) signals.push_back({state, prepared[state]});
  for (const std::string& input : inputs) signals.push_back({input, prepared[input]});
  const RegressorLibrary library = speed.empty()
                                       ? BuildLibrary(signals, {}, LibraryOptions{})
                                       : SpeedScaledLibrary(signals, inputs, prepared[speed], speed);
  const Eigen::MatrixXd& a = library.columns;
  std::vector<TermProposal> out;
  for (const auto& [state, y] : residual) {
    const double yy = y.squaredNorm();
    if (!(yy > 0.0)) continue;
    std::vector<int> chosen;
    std::vector<double> errs;
    Eigen::MatrixXd q(a.rows(), 0);  // orthonormal basis of the chosen columns
    for (int step = 0; step < per_state; ++step) {
      int best = -1;
      double best_err = 0.0;
      Eigen::VectorXd best_w;
      for (Eigen::Index j = 0; j < a.cols(); ++j) {
        if (std::find(chosen.begin(), chosen.end(), j) != chosen.end()) continue;
        Eigen::VectorXd w = a.col(j);
        if (q.cols() > 0) w -= q * (q.transpose() * w);
        const double ww = w.squaredNorm();
        if (!(ww > 1e-18 * a.col(j).squaredNorm()) || !(ww > 0.0)) continue;
        const double g = w.dot(y);
        const double err = g * g / (ww * yy);
        if (err > best_err) {
          best = static_cast<int>(j);
          best_err = err;
          best_w = w / std::sqrt(ww);
        }
      }
      if (best < 0) break;
      chosen.push_back(best);
      errs.push_back(best_err);
      q.conservativeResize(Eigen::NoChange, q.cols() + 1);
      q.col(q.cols() - 1) = best_w;
    }
    if (chosen.empty()) continue;
    Eigen::MatrixXd columns(a.rows(), static_cast<Eigen::Index>(chosen.size()));
    for (size_t i = 0; i < chosen.size(); ++i) columns.col(static_cast<Eigen::Index>(i)) = a.col(chosen[i]);
    const Eigen::VectorXd w = columns.colPivHouseholderQr().solve(y);
    for (size_t i = 0; i < chosen.size(); ++i) {
      Effect e{EffectKind::kMissingTerm,
               {{"coefficient", w(static_cast<Eigen::Index>(i))}},
               {},
               state,
               library.names[chosen[i]]};
      out.push_back({std::move(e), errs[i]});
    }
  }
  return out;
}

}  // namespace usvid::hybrid
