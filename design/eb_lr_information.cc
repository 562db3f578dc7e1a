#include "design/eb_lr_information.h"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "core/error.h"
#include "design/steady_state_sensitivity.h"
#include "methods/eb_lr/eb_lr.h"
#include "methods/eb_lr/transient_pieces.h"
#include "preprocessing/derivative.h"
#include "simulators/eb2dof.h"

namespace usvid::design {
namespace {

using V = Eb2Dof;

// The inverse of a symmetric positive semi-definite matrix; a direction without information
// keeps a finite, huge variance (as information.cc does).
Eigen::MatrixXd Inverse(const Eigen::MatrixXd& a) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(a);
  const Eigen::VectorXd lambda = eig.eigenvalues().cwiseMax(eig.eigenvalues().maxCoeff() * 1e-300);
  return eig.eigenvectors() * lambda.cwiseInverse().asDiagonal() * eig.eigenvectors().transpose();
}

struct Span {
  Eigen::Index first = 0, last = -1;
};

// Each dynamic state's error after eb-lr's smoothing, RMS over the windows' end points.
std::vector<double> SmoothedEndError(const Dataset& trial, const Dataset& noisy,
                                     const std::vector<Span>& spans) {
  const Eigen::VectorXd& t = noisy.t();
  const double dt = (t(t.size() - 1) - t(0)) / static_cast<double>(t.size() - 1);
  std::vector<Eigen::VectorXd> inputs;
  for (std::string_view u : V::kInputNames) inputs.push_back(noisy[std::string(u)]);
  const auto breaks = StepBreaks(inputs, eb_lr::EbLrOptions{}.steady.input_tolerance);
  std::vector<double> out;
  for (std::string_view name : V::kStateNames) {
    if (IsPositionOrHeading(name)) continue;
    const std::string s(name);
    const Eigen::VectorXd smooth =
        SmoothAndDifferentiate(noisy[s], dt, DerivativeMethod{}, breaks).value;
    double ss = 0.0, n = 0.0;
    for (const Span& w : spans)
      for (const Eigen::Index k : {w.first, w.last}) {
        ss += std::pow(smooth(k) - trial[s](k), 2);
        n += 1.0;
      }
    out.push_back(std::sqrt(ss / n));
  }
  return out;
}

// How eb-lr's masses follow an error in its sigma (relative units; rows the masses, columns
// sigma's terms, in eb2dof's order). For equation i, the mass rows are int m dx_i = int (tau_i -
// sigma_i) dt over the transient pieces, A c = b with A_pj = int mu_j dx_i; an error ds of sigma
// moves b by -G ds, G_pj = int phi_j dt, and so c by -K ds, K = (A^T A)^-1 A^T G.
Eigen::MatrixXd MassOnSigma(const Dataset& trial, const std::vector<Span>& windows) {
  const eb_lr::EbLrOptions o;
  const Eigen::VectorXd& t = trial.t();
  const double dt = (t(t.size() - 1) - t(0)) / static_cast<double>(t.size() - 1);
  std::vector<eb_lr::SteadyWindow> steady;
  for (const Span& w : windows) steady.push_back({w.first, w.last});
  const auto runs = eb_lr::TransientRuns(
      t.size(), steady, static_cast<Eigen::Index>(std::round(o.transient_margin_s / dt)));
  const auto pieces = eb_lr::TransientPieces(
      runs, std::max<Eigen::Index>(1, static_cast<Eigen::Index>(std::round(o.transient_window_s / dt))));
  const Eigen::VectorXd& speed = trial["U"];
  const Eigen::VectorXd& rate = trial["r"];
  // eb2dof's order: m_U's, m_r's, sigma_U's, sigma_r's terms (design/method_problem.h).
  const std::array<const std::vector<eb_lr::Monomial>*, 2> mass_basis = {&o.mass_speed_basis,
                                                                         &o.mass_rate_basis};
  const std::array<const std::vector<eb_lr::Monomial>*, 2> sigma_basis = {&o.sigma_speed_basis,
                                                                          &o.sigma_rate_basis};
  const std::array<Eigen::Index, 2> mass_at = {0, static_cast<Eigen::Index>(o.mass_speed_basis.size())};
  const Eigen::Index sigma0 = mass_at[1] + static_cast<Eigen::Index>(o.mass_rate_basis.size());
  const std::array<Eigen::Index, 2> sigma_at = {
      sigma0, sigma0 + static_cast<Eigen::Index>(o.sigma_speed_basis.size())};
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(V::kParams, V::kParams);
  for (int i = 0; i < 2; ++i) {
    const Eigen::VectorXd& x = i == 0 ? speed : rate;
    const auto rows = static_cast<Eigen::Index>(pieces.size());
    const auto nm = static_cast<Eigen::Index>(mass_basis[i]->size());
    const auto ns = static_cast<Eigen::Index>(sigma_basis[i]->size());
    Eigen::MatrixXd a(rows, nm), g(rows, ns);
    for (Eigen::Index p = 0; p < rows; ++p) {
      const eb_lr::SteadyWindow& span = pieces[p];
      for (Eigen::Index j = 0; j < nm; ++j)
        a(p, j) = eb_lr::Stieltjes(x, span, [&](Eigen::Index n) {
          return (*mass_basis[i])[j].Evaluate(speed(n), rate(n));
        });
      for (Eigen::Index j = 0; j < ns; ++j)
        g(p, j) = eb_lr::Stieltjes(t, span, [&](Eigen::Index n) {
          return (*sigma_basis[i])[j].Evaluate(speed(n), rate(n));
        });
    }
    k.block(mass_at[i], sigma_at[i], nm, ns) = a.colPivHouseholderQr().solve(g);
  }
  // Relative units: dc/c = -diag(1/c) K diag(s) ds/s.
  const Eigen::VectorXd p =
      Eigen::Map<const Eigen::VectorXd>(V::kDefaultParams.data(), V::kParams);
  return p.cwiseInverse().asDiagonal() * k * p.asDiagonal();
}

}  // namespace

Eigen::MatrixXd EbLrCovariance(const Eigen::MatrixXd& record_information, const Dataset& trial,
                               const Dataset& noisy,
                               const std::vector<std::pair<double, double>>& windows,
                               const NoiseModel& noise) {
  constexpr int kDyn = DynamicStateCount<V>();
  std::vector<Eigen::Index> mass, sigma;
  for (int j = 0; j < V::kParams; ++j)
    (V::kParamGroups[j] == ParamGroup::kInertia ? mass : sigma).push_back(j);
  const std::vector<double> p(V::kDefaultParams.begin(), V::kDefaultParams.end());
  const Eigen::VectorXd scale = Eigen::Map<const Eigen::VectorXd>(p.data(), V::kParams);
  std::vector<double> noise_sd;
  for (std::string_view s : V::kStateNames)
    if (!IsPositionOrHeading(s)) noise_sd.push_back(noise.at(std::string(s)));

  const Eigen::VectorXd& t = trial.t();
  std::vector<Span> spans;
  for (const auto& [start, end] : windows) {
    Span w;
    w.first = std::lower_bound(t.data(), t.data() + t.size(), start - 1e-9) - t.data();
    w.last = (std::upper_bound(t.data(), t.data() + t.size(), end + 1e-9) - t.data()) - 1;
    if (w.last > w.first) spans.push_back(w);
  }
  if (spans.empty()) throw InputError("design: eb-lr found no steady window");
  const std::vector<double> end_error = SmoothedEndError(trial, noisy, spans);

  // Stage 1: sigma's information from the windows, one row per window and equation.
  Eigen::MatrixXd windows_information = Eigen::MatrixXd::Zero(V::kParams, V::kParams);
  for (const Span& w : spans) {
    const auto n = static_cast<double>(w.last - w.first + 1);
    std::vector<double> x(V::kStates), tau(V::kInputs);
    for (int i = 0; i < V::kStates; ++i)
      x[i] = trial[std::string(V::kStateNames[i])].segment(w.first, w.last - w.first + 1).mean();
    for (int i = 0; i < V::kInputs; ++i)
      tau[i] = trial[std::string(V::kInputNames[i])].segment(w.first, w.last - w.first + 1).mean();
    const DerivativeJacobians d = DerivativeJacobiansAt<V>(x, tau, p);
    const double seconds = t(w.last) - t(w.first);
    for (int i = 0; i < kDyn; ++i) {
      double var = 2.0 * std::pow(end_error[i] / seconds, 2);
      for (int k = 0; k < kDyn; ++k) var += std::pow(d.fx(i, k) * noise_sd[k], 2) / n;
      const Eigen::RowVectorXd row = d.fp.row(i) * scale.asDiagonal();
      windows_information += row.transpose() * row / var;
    }
  }
  const Eigen::MatrixXd info_ss = windows_information(sigma, sigma);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(info_ss);
  if (!(eig.eigenvalues().minCoeff() > 1e-12 * eig.eigenvalues().maxCoeff()))
    throw InputError("design: eb-lr: the steady windows do not pin sigma (" +
                     std::to_string(spans.size()) + " windows)");
  const Eigen::MatrixXd cov_ss = Inverse(info_ss);

  // Stage 2: the masses from the transients, with sigma's error carried over as eb-lr's own
  // regression carries it.
  const Eigen::MatrixXd cov_mm0 = Inverse(record_information(mass, mass));
  const Eigen::MatrixXd k = MassOnSigma(trial, spans)(mass, sigma);
  Eigen::MatrixXd cov = Eigen::MatrixXd::Zero(V::kParams, V::kParams);
  cov(sigma, sigma) = cov_ss;
  cov(mass, mass) = cov_mm0 + k * cov_ss * k.transpose();
  cov(mass, sigma) = -k * cov_ss;
  cov(sigma, mass) = cov(mass, sigma).transpose();
  return cov;
}

}  // namespace usvid::design
