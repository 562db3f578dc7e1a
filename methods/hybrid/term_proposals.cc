#include "methods/hybrid/term_proposals.h"

#include <Eigen/QR>

#include "preprocessing/regressor_library.h"

namespace usvid::hybrid {
namespace {

// Products of two signals and |x| x (the quadratic columns of BuildLibrary), and u*u*input for
// each input.
RegressorLibrary SpeedScaledLibrary(const std::vector<NamedSignal>& signals,
                                    const std::vector<std::string>& inputs,
                                    const Eigen::VectorXd& u, const std::string& speed) {
  LibraryOptions quadratic;
  quadratic.constant = false;
  const RegressorLibrary all = BuildLibrary(signals, {}, quadratic);
  std::vector<Eigen::Index> keep;
  for (Eigen::Index j = 0; j < all.columns.cols(); ++j)
    if (std::none_of(signals.begin(), signals.end(),
                     [&](const NamedSignal& s) { return s.name == all.names[j]; }))
      keep.push_back(j);
  RegressorLibrary out;
  out.columns.resize(all.columns.rows(), static_cast<Eigen::Index>(keep.size()));
  for (size_t i = 0; i < keep.size(); ++i) {
    out.names.push_back(all.names[keep[i]]);
    out.columns.col(static_cast<Eigen::Index>(i)) = all.columns.col(keep[i]);
  }
  for (const NamedSignal& s : signals) {
    if (std::find(inputs.begin(), inputs.end(), s.name) == inputs.end()) continue;
    out.names.push_back(speed + "*" + speed + "*" + s.name);
    out.columns.conservativeResize(Eigen::NoChange, out.columns.cols() + 1);
    out.columns.col(out.columns.cols() - 1) = u.cwiseProduct(u).cwiseProduct(s.values);
  }
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
