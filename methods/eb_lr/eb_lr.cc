#include "methods/eb_lr/eb_lr.h"

#include <Eigen/QR>
#include <algorithm>
#include <array>
#include <cmath>

#include "core/error.h"
#include "core/parse_number.h"
#include "methods/eb_lr/output_error.h"
#include "methods/eb_lr/transient_pieces.h"
#include "preprocessing/derivative.h"

namespace usvid::eb_lr {
namespace {

using Basis = std::vector<Monomial>;
using Span = SteadyWindow;  // samples [first, last]

// Index 0 is the speed equation (and state, and input), 1 the rate equation.
struct Signals {
  Eigen::VectorXd t;
  std::array<Eigen::VectorXd, 2> x, s, u;  // raw states, smoothed states, inputs
  Eigen::VectorXd q;  // the thrust's loss channel (EbLrOptions::thrust_loss_channel), or empty
};

// One row of M(x) x' + sigma(x) = tau: its bases, coefficients and fit residuals.
struct Equation {
  std::string state, input;
  Basis sigma_basis, mass_basis;       // sigma's: the terms kept (ChooseSigmaTerms)
  Basis sigma_given;                   // the basis the options gave
  bool sigma_from_transients = false;  // no window excites a term: fitted with the mass
  std::vector<std::string> sigma_terms, mass_terms;
  Eigen::VectorXd sigma, mass, sigma_residual, mass_residual;
  bool thrust_loss_term = false;  // sigma gains k q U (EbLrOptions::thrust_loss_channel)
  double thrust_loss = 0.0;       // k
  std::string thrust_loss_text;   // "q*U"
  double output_error_rms = -1.0;
  int output_error_iterations = 0;

  // sigma at (speed, rate) with the loss channel at q.
  double Sigma(double speed, double rate, double q) const {
    return Combination(sigma_basis, sigma, speed, rate) +
           (thrust_loss_term ? thrust_loss * q * speed : 0.0);
  }
};

void CheckOptions(const EbLrOptions& o) {
  const std::pair<const Basis*, const char*> bases[] = {{&o.sigma_speed_basis, "sigma_speed_basis"},
                                                        {&o.sigma_rate_basis, "sigma_rate_basis"},
                                                        {&o.mass_speed_basis, "mass_speed_basis"},
                                                        {&o.mass_rate_basis, "mass_rate_basis"}};
  for (const auto& [basis, name] : bases) {
    if (basis->empty()) throw InputError(std::string("eb-lr option ") + name + ": empty basis");
    for (const Monomial& m : *basis)
      if (m.speed_power < 0 || m.rate_power < 0 || (m.abs_rate && m.rate_power < 1))
        throw InputError(std::string("eb-lr option ") + name + ": bad term " + m.Text("U", "r"));
  }
  if (!(o.transient_window_s > 0.0 && std::isfinite(o.transient_window_s)))
    throw InputError("eb-lr option transient_window_s: must be positive, got " +
                     FormatNumber(o.transient_window_s));
  if (!(o.transient_margin_s >= 0.0 && std::isfinite(o.transient_margin_s)))
    throw InputError("eb-lr option transient_margin_s: must be >= 0, got " +
                     FormatNumber(o.transient_margin_s));
  if (o.refinements < 0 || o.refinements > 100)
    throw InputError("eb-lr option refinements: must be 0 to 100, got " +
                     std::to_string(o.refinements));
}

Eigen::VectorXd Column(const Dataset& data, const std::string& name, const std::string& role) {
  const Channel* c = data.Find(name);
  if (c == nullptr) throw InputError("eb-lr: the data have no " + role + " channel '" + name + "'");
  if (!c->FullySampled() || !c->values().allFinite())
    throw InputError("eb-lr: channel '" + name +
                     "' is not fully sampled with finite values (resample multi-rate data first)");
  return c->values();
}

// Least squares a c = b, columns divided by `scale` for conditioning; a term the rows do not
// separate from the others (numerical rank) is bad input, named in the message.
Eigen::VectorXd Solve(const Eigen::MatrixXd& a, const Eigen::VectorXd& b,
                      const Eigen::VectorXd& scale, const std::vector<std::string>& terms,
                      const std::string& what) {
  for (Eigen::Index j = 0; j < a.cols(); ++j)
    if (!(scale(j) > 0.0))
      throw InputError("eb-lr: " + what + ": the data do not excite the term " + terms[j]);
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a * scale.cwiseInverse().asDiagonal());
  qr.setThreshold(1e-9);
  if (qr.rank() < a.cols()) {
    std::string names;
    for (Eigen::Index j = qr.rank(); j < a.cols(); ++j)
      names += (names.empty() ? "" : ", ") + terms[qr.colsPermutation().indices()(j)];
    throw InputError("eb-lr: " + what + ": the data do not separate the term(s) " + names +
                     " from the others (too few or too similar steady states)");
  }
  return qr.solve(b).cwiseQuotient(scale);
}

// sigma from the steady windows, each corrected by what it still accelerates under the mass.
// With the thrust's loss, k is one more column, the window's mean of q U: at a held command
// the windows of a step grid reach several speeds (straight and in turns of each yaw step), so
// the steady states separate k q U from sigma(U, r). The transients cannot: near a steady
// state the loss scales the force as (1 - k U) / m_U(U), which a mass slope nearly matches.
void FitSigma(const Signals& s, int i, const std::vector<Span>& windows, Equation& eq) {
  const Basis& basis = eq.sigma_basis;
  const auto terms = static_cast<Eigen::Index>(basis.size());
  const Eigen::Index cols = terms + (eq.thrust_loss_term ? 1 : 0);
  const auto rows = static_cast<Eigen::Index>(windows.size());
  Eigen::MatrixXd a(rows, cols);
  Eigen::VectorXd b(rows), scale(cols);
  for (Eigen::Index w = 0; w < rows; ++w) {
    const Span& span = windows[w];
    const Eigen::Index len = span.last - span.first + 1;
    const double speed = s.x[0].segment(span.first, len).mean();
    const double rate = s.x[1].segment(span.first, len).mean();
    for (Eigen::Index j = 0; j < terms; ++j) a(w, j) = basis[j].Evaluate(speed, rate);
    if (eq.thrust_loss_term)
      a(w, terms) =
          s.q.segment(span.first, len).cwiseProduct(s.x[0].segment(span.first, len)).mean();
    const double accelerating = Stieltjes(s.s[i], span, [&](Eigen::Index k) {
      return Combination(eq.mass_basis, eq.mass, s.s[0](k), s.s[1](k));
    });
    b(w) =
        s.u[i].segment(span.first, len).mean() - accelerating / (s.t(span.last) - s.t(span.first));
  }
  const double speed_max = s.x[0].cwiseAbs().maxCoeff(), rate_max = s.x[1].cwiseAbs().maxCoeff();
  for (Eigen::Index j = 0; j < terms; ++j)
    scale(j) = std::abs(basis[j].Evaluate(speed_max, rate_max));
  if (eq.thrust_loss_term) scale(terms) = s.q.cwiseAbs().maxCoeff() * speed_max;
  std::vector<std::string> names = eq.sigma_terms;
  if (eq.thrust_loss_term) names.push_back(eq.thrust_loss_text);
  const Eigen::VectorXd c = Solve(a, b, scale, names, "sigma_" + eq.state);
  eq.sigma = c.head(terms);
  if (eq.thrust_loss_term) eq.thrust_loss = c(terms);
  eq.sigma_residual = b - a * c;
}

// M from the transient pieces: sum_j c_j int mu_j dx = int (tau - sigma) dt, sigma with the
// thrust's loss k q U. With sigma_from_transients, sigma's one term a phi is fitted with them:
// sum_j c_j int mu_j dx + a int phi dt = int tau dt.
void FitMass(const Signals& s, int i, const std::vector<Span>& pieces, Equation& eq) {
  const Basis& basis = eq.mass_basis;
  const auto terms = static_cast<Eigen::Index>(basis.size());
  const bool joint = eq.sigma_from_transients;
  const Eigen::Index cols = terms + (joint ? 1 : 0);
  const auto rows = static_cast<Eigen::Index>(pieces.size());
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(rows, cols);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(rows);
  for (Eigen::Index p = 0; p < rows; ++p) {
    const Span& span = pieces[p];
    for (Eigen::Index j = 0; j < terms; ++j)
      a(p, j) = Stieltjes(s.s[i], span,
                          [&](Eigen::Index k) { return basis[j].Evaluate(s.s[0](k), s.s[1](k)); });
    for (Eigen::Index k = span.first; k < span.last; ++k) {
      const double h = s.t(k + 1) - s.t(k);
      if (joint) {
        const Monomial& phi = eq.sigma_basis.front();
        a(p, terms) +=
            0.5 *
            (phi.Evaluate(s.s[0](k), s.s[1](k)) + phi.Evaluate(s.s[0](k + 1), s.s[1](k + 1))) * h;
        b(p) += s.u[i](k) * h;
        continue;
      }
      const double q = eq.thrust_loss_term ? s.q(k) : 0.0;
      const double sigma0 = eq.Sigma(s.s[0](k), s.s[1](k), q);
      const double sigma1 = eq.Sigma(s.s[0](k + 1), s.s[1](k + 1), q);
      b(p) += (s.u[i](k) - 0.5 * (sigma0 + sigma1)) * h;
    }
  }
  std::vector<std::string> names = eq.mass_terms;
  if (joint) names.push_back(eq.sigma_terms.front() + " (of sigma_" + eq.state + ")");
  const Eigen::VectorXd c = Solve(a, b, a.colwise().norm().transpose(), names, "m_" + eq.state);
  eq.mass = c.head(terms);
  if (joint) eq.sigma = c.tail(1);
  eq.mass_residual = b - a * c;
}

// sigma's residual at each window: what the window's mean input leaves of sigma at its mean state
// (for an equation whose sigma the transients gave).
Eigen::VectorXd WindowResiduals(const Signals& s, int i, const std::vector<Span>& windows,
                                const Equation& eq) {
  Eigen::VectorXd r(static_cast<Eigen::Index>(windows.size()));
  for (size_t w = 0; w < windows.size(); ++w) {
    const Eigen::Index f = windows[w].first, len = windows[w].last - f + 1;
    const double q = eq.thrust_loss_term ? s.q.segment(f, len).mean() : 0.0;
    r(static_cast<Eigen::Index>(w)) =
        s.u[i].segment(f, len).mean() -
        eq.Sigma(s.x[0].segment(f, len).mean(), s.x[1].segment(f, len).mean(), q);
  }
  return r;
}

std::string Sum(const Basis& basis, const Eigen::VectorXd& c, const std::string& speed,
                const std::string& rate) {
  std::string s;
  for (size_t j = 0; j < basis.size(); ++j) {
    const std::string term = basis[j].Text(speed, rate);
    const std::string value = FormatNumber(s.empty() ? c(j) : std::abs(c(j)));
    s += s.empty() ? "" : (c(j) < 0 ? " - " : " + ");
    s += term == "1" ? value : value + "*" + term;
  }
  return s;
}

double Rms(const Eigen::VectorXd& v) {
  return v.size() ? std::sqrt(v.squaredNorm() / static_cast<double>(v.size())) : 0.0;
}

// The time step of the data, whose grid must be uniform within each stretch, with one step, and
// at least 20 rows long.
double UniformStep(const Eigen::VectorXd& t, const std::vector<Stretch>& stretches) {
  const Eigen::Index n = t.size();
  if (n < 20) throw InputError("eb-lr: the data have " + std::to_string(n) + " rows; need 20");
  double dt = 0.0;
  for (const Stretch& st : stretches)
    if (st.rows() > 1) {
      dt = (t(st.end - 1) - t(st.first)) / static_cast<double>(st.rows() - 1);
      break;
    }
  for (const Stretch& st : stretches)
    for (Eigen::Index k = st.first + 1; k < st.end; ++k)
      if (std::abs(t(k) - t(k - 1) - dt) > 1e-3 * dt)
        throw InputError("eb-lr: the time grid is not uniform at t = " + FormatNumber(t(k)) +
                         " s: eb-lr fits one record without gaps (resample it first)");
  return dt;
}

// The speed and rate equations' states, inputs and bases (their fits still to come).
std::array<Equation, 2> NewEquations(const std::string& speed, const std::string& rate,
                                     const std::string& thrust_input, const std::string& yaw_input,
                                     const EbLrOptions& options) {
  std::array<Equation, 2> eq;
  eq[0].state = speed;
  eq[1].state = rate;
  eq[0].input = thrust_input;
  eq[1].input = yaw_input;
  eq[0].sigma_basis = eq[0].sigma_given = options.sigma_speed_basis;
  eq[1].sigma_basis = eq[1].sigma_given = options.sigma_rate_basis;
  eq[0].mass_basis = options.mass_speed_basis;
  eq[1].mass_basis = options.mass_rate_basis;
  eq[0].thrust_loss_term = !options.thrust_loss_channel.empty();
  return eq;
}

// The inputs that are held at each step of the experiment: the commands, when the regression's
// inputs are forces that slew to their new values and carry measurement noise.
std::array<Eigen::VectorXd, 2> HeldInputs(const Dataset& data, const EbLrOptions& options,
                                          const std::array<Eigen::VectorXd, 2>& inputs) {
  std::array<Eigen::VectorXd, 2> held = inputs;
  if (!options.held_inputs.empty()) {
    if (options.held_inputs.size() != 2)
      throw InputError("eb-lr option held_inputs: names a thrust and a yaw command, got " +
                       std::to_string(options.held_inputs.size()) + " channels");
    held = {Column(data, options.held_inputs[0], "held thrust command"),
            Column(data, options.held_inputs[1], "held yaw command")};
  }
  return held;
}

// Each equation's term names, in the caller's channel names.
void SetTermNames(std::array<Equation, 2>& eq) {
  for (Equation& e : eq) {
    e.sigma_terms.clear();
    e.mass_terms.clear();
    for (const Monomial& m : e.sigma_basis)
      e.sigma_terms.push_back(m.Text(eq[0].state, eq[1].state));
    for (const Monomial& m : e.mass_basis) e.mass_terms.push_back(m.Text(eq[0].state, eq[1].state));
  }
}

// Throws InputError for a held input that is constant: the thrust unless constant_thrust; the
// yaw always (a record that never turns has no rate equation).
void CheckHeldInputs(const std::array<Eigen::VectorXd, 2>& held, const std::array<Equation, 2>& eq,
                     const EbLrOptions& options) {
  for (int i = 0; i < 2; ++i) {
    if (held[i].maxCoeff() != held[i].minCoeff() || (i == 0 && options.constant_thrust)) continue;
    const std::string name = options.held_inputs.empty() ? eq[i].input : options.held_inputs[i];
    throw InputError("eb-lr: the input '" + name + "' is constant; a step grid steps both inputs" +
                     (i == 0 ? " (constant_thrust: fit sigma_" + eq[0].state +
                                   " on the speeds one thrust reaches)"
                             : ""));
  }
}

// Each state smoothed on each stretch (its derivative's smoothing broken at the input steps),
// each equation's term names, and its mass started at zero.
void SmoothStates(double dt, const std::vector<Stretch>& stretches,
                  const std::vector<Eigen::Index>& breaks, Signals& s,
                  std::array<Equation, 2>& eq) {
  for (int i = 0; i < 2; ++i) {
    if (stretches.size() == 1) {
      s.s[i] = SmoothAndDifferentiate(s.x[i], dt, DerivativeMethod{}, breaks).value;
    } else {
      s.s[i].resize(s.x[i].size());
      for (const Stretch& st : stretches) {
        std::vector<Eigen::Index> inside;
        for (const Eigen::Index b : breaks)
          if (b > st.first && b < st.end) inside.push_back(b - st.first);
        s.s[i].segment(st.first, st.rows()) =
            SmoothAndDifferentiate(s.x[i].segment(st.first, st.rows()), dt, DerivativeMethod{},
                                   inside)
                .value;
      }
    }
    eq[i].mass = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(eq[i].mass_basis.size()));
  }
  SetTermNames(eq);
}

// Throws InputError when there are fewer steady windows than an equation's sigma terms.
void CheckWindows(const std::vector<Span>& windows, const std::array<Equation, 2>& eq) {
  for (const Equation& e : eq)
    if (windows.size() < e.sigma_terms.size())
      throw InputError("eb-lr: found " + std::to_string(windows.size()) +
                       " steady windows; sigma_" + e.state + " on " + BasisText(e.sigma_basis) +
                       " needs at least " + std::to_string(e.sigma_terms.size()) +
                       " (hold more input steps to steady state, or relax min_window_s or "
                       "max_relative_rate)");
}

// Throws InputError for a record without a single steady window: nothing to lower the order to.
void CheckAnyWindow(const std::vector<Span>& windows, const std::array<Equation, 2>& eq,
                    const EbLrOptions& o) {
  if (!windows.empty()) return;
  throw InputError(
      "eb-lr: found 0 steady windows: the record has no steady state (no stretch of "
      "held inputs in which " +
      eq[0].state + " and " + eq[1].state + " settle for " + FormatNumber(o.steady.min_window_s) +
      " s), and eb-lr's damping sigma comes from steady states");
}

// Lowers an equation's sigma basis to the terms the windows excite and separate (eb_lr.h), in
// the basis's order, the thrust's loss last; none: its first term, fitted with the mass from the
// transients. Says what it dropped in `warnings`.
void ChooseSigmaTerms(const Signals& s, const std::vector<Span>& windows, Equation& eq,
                      nlohmann::json& warnings) {
  const Basis& given = eq.sigma_given;
  const auto terms = static_cast<Eigen::Index>(given.size());
  const Eigen::Index cols = terms + (eq.thrust_loss_term ? 1 : 0);
  const auto rows = static_cast<Eigen::Index>(windows.size());
  Eigen::MatrixXd a(rows, cols);
  Eigen::VectorXd scale(cols);
  for (Eigen::Index w = 0; w < rows; ++w) {
    const Eigen::Index f = windows[w].first, len = windows[w].last - f + 1;
    const double speed = s.x[0].segment(f, len).mean(), rate = s.x[1].segment(f, len).mean();
    for (Eigen::Index j = 0; j < terms; ++j) a(w, j) = given[j].Evaluate(speed, rate);
    if (eq.thrust_loss_term)
      a(w, terms) = s.q.segment(f, len).cwiseProduct(s.x[0].segment(f, len)).mean();
  }
  const double speed_max = s.x[0].cwiseAbs().maxCoeff(), rate_max = s.x[1].cwiseAbs().maxCoeff();
  for (Eigen::Index j = 0; j < terms; ++j)
    scale(j) = std::abs(given[j].Evaluate(speed_max, rate_max));
  if (eq.thrust_loss_term) scale(terms) = s.q.cwiseAbs().maxCoeff() * speed_max;
  // At most one term fewer than windows, so that the windows also test the terms kept (two
  // windows fitted exactly by two terms drew a parabola through two turns); a full basis with
  // more windows than terms is kept whole.
  const Eigen::Index limit = rows > cols ? cols : std::max<Eigen::Index>(1, rows - 1);
  std::vector<Eigen::Index> kept;
  for (Eigen::Index j = 0; j < cols && static_cast<Eigen::Index>(kept.size()) < limit; ++j) {
    if (!(scale(j) > 0.0) || a.col(j).cwiseAbs().maxCoeff() < 0.01 * scale(j)) continue;
    std::vector<Eigen::Index> trial = kept;
    trial.push_back(j);
    Eigen::MatrixXd m(rows, static_cast<Eigen::Index>(trial.size()));
    for (size_t c = 0; c < trial.size(); ++c)
      m.col(static_cast<Eigen::Index>(c)) = a.col(trial[c]) / scale(trial[c]);
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(m);
    qr.setThreshold(1e-6);
    if (qr.rank() == m.cols()) kept = std::move(trial);
  }
  if (static_cast<Eigen::Index>(kept.size()) == cols) return;
  Basis basis;
  std::string kept_text, dropped_text;
  bool loss = false;
  for (Eigen::Index j = 0; j < cols; ++j) {
    const bool in = std::ranges::find(kept, j) != kept.end();
    const std::string name = j < terms ? given[j].Text("U", "r") : eq.thrust_loss_text;
    std::string& text = in ? kept_text : dropped_text;
    text += (text.empty() ? "" : ", ") + name;
    if (in && j < terms) basis.push_back(given[j]);
    if (in && j == terms) loss = true;
  }
  const std::string what = "sigma_" + eq.state;
  if (basis.empty()) {
    eq.sigma_from_transients = true;
    basis = {given.front()};
    loss = false;
    warnings.push_back(what + ": no steady window excites a term of " + BasisText(given) + " (" +
                       std::to_string(rows) + " windows); its first term " +
                       given.front().Text("U", "r") +
                       " fitted with the mass from the transients, the others dropped");
  } else {
    warnings.push_back(what + " lowered to " + kept_text + " (" + std::to_string(kept.size()) +
                       " of " + std::to_string(cols) + " terms): " + std::to_string(rows) +
                       " steady windows do not excite or separate " + dropped_text);
  }
  eq.sigma_basis = std::move(basis);
  eq.thrust_loss_term = loss;
}

// Throws InputError when there are fewer transient pieces than an equation's mass terms (and
// its sigma term, fitted with them).
void CheckPieces(const std::vector<Span>& pieces, const std::array<Equation, 2>& eq) {
  for (const Equation& e : eq)
    if (pieces.size() < e.mass_terms.size() + (e.sigma_from_transients ? 1 : 0))
      throw InputError("eb-lr: " + std::to_string(pieces.size()) + " transient pieces; m_" +
                       e.state + " on " + BasisText(e.mass_basis) + " needs at least " +
                       std::to_string(e.mass_terms.size()));
}

// sigma and M of both equations, fitted in turn 1 + options.refinements times, the mass (when
// asked) by output error over the transient runs.
void FitEquations(const Signals& s, const std::vector<Span>& windows, const std::vector<Span>& runs,
                  const std::vector<Span>& pieces, const EbLrOptions& options,
                  std::array<Equation, 2>& eq) {
  for (int pass = 0; pass <= options.refinements; ++pass)
    for (int i = 0; i < 2; ++i) {
      if (!eq[i].sigma_from_transients) FitSigma(s, i, windows, eq[i]);
      FitMass(s, i, pieces, eq[i]);
      if (eq[i].sigma_from_transients) eq[i].sigma_residual = WindowResiduals(s, i, windows, eq[i]);
      if (!options.output_error_mass) continue;
      const MassOutputErrorFit fit =
          FitMassByOutputError({s.t, s.s[0], s.s[1], s.x[i], s.u[i], i, eq[i].sigma_basis,
                                eq[i].sigma, eq[i].mass_basis, runs, s.q, eq[i].thrust_loss},
                               eq[i].mass);
      eq[i].mass = fit.mass;
      eq[i].output_error_rms = fit.rms;
      eq[i].output_error_iterations = fit.iterations;
    }
}

// Each steady window: its times, mean states and inputs, and sigma's residual there.
nlohmann::json WindowsJson(const Signals& s, const std::vector<Span>& windows,
                           const std::array<Equation, 2>& eq) {
  nlohmann::json list = nlohmann::json::array();
  for (size_t w = 0; w < windows.size(); ++w) {
    const Eigen::Index f = windows[w].first, len = windows[w].last - f + 1;
    list.push_back({{"start_s", s.t(f)},
                    {"end_s", s.t(windows[w].last)},
                    {eq[0].state, s.x[0].segment(f, len).mean()},
                    {eq[1].state, s.x[1].segment(f, len).mean()},
                    {eq[0].input, s.u[0].segment(f, len).mean()},
                    {eq[1].input, s.u[1].segment(f, len).mean()},
                    {"residual_" + eq[0].state, eq[0].sigma_residual(w)},
                    {"residual_" + eq[1].state, eq[1].sigma_residual(w)}});
  }
  return list;
}

// One equation's parameters and expression into `out`, its fit summary into out.details, and a
// warning when its mass is not positive over the data.
void ReportEquation(const Equation& e, double noise_sd, const Signals& s, bool output_error_mass,
                    const std::string& speed, const std::string& rate, EbLrIdentification& out) {
  nlohmann::json& info = out.details;
  info["noise_sd"][e.state] = noise_sd;
  info["fit"]["sigma_" + e.state] = {
      {"basis", BasisText(e.sigma_basis) + (e.thrust_loss_term ? "," + e.thrust_loss_text : "")},
      {"rms", Rms(e.sigma_residual)}};
  info["fit"]["m_" + e.state] = {{"basis", BasisText(e.mass_basis)}, {"rms", Rms(e.mass_residual)}};
  if (output_error_mass) {
    info["fit"]["m_" + e.state]["output_error_rms"] = e.output_error_rms;
    info["fit"]["m_" + e.state]["output_error_iterations"] = e.output_error_iterations;
  }
  for (Eigen::Index j = 0; j < e.sigma.size(); ++j)
    out.parameters["sigma_" + e.state + "." + e.sigma_terms[j]] = e.sigma(j);
  std::string sigma_text = Sum(e.sigma_basis, e.sigma, speed, rate);
  if (e.thrust_loss_term) {
    out.parameters["sigma_" + e.state + "." + e.thrust_loss_text] = e.thrust_loss;
    sigma_text += (e.thrust_loss < 0 ? " - " : " + ") + FormatNumber(std::abs(e.thrust_loss)) +
                  "*" + e.thrust_loss_text;
  }
  for (size_t j = 0; j < e.mass_terms.size(); ++j)
    out.parameters["m_" + e.state + "." + e.mass_terms[j]] = e.mass(j);
  out.equations[e.state] =
      "(" + e.input + " - (" + sigma_text + ")) / (" + Sum(e.mass_basis, e.mass, speed, rate) + ")";
  double least = INFINITY;
  for (Eigen::Index k = 0; k < s.t.size(); ++k)
    least = std::min(least, Combination(e.mass_basis, e.mass, s.x[0](k), s.x[1](k)));
  if (!(least > 0.0))
    info["warnings"].push_back("m_" + e.state + " reaches " + FormatNumber(least) +
                               " over the data: the mass must be positive");
}

// With order auto: a mass that is not positive over the data (its slope in U fitted to the
// transients of a few steps, which barely tell it from the constant) is lowered to its first
// term, a constant, and said in `warnings`. Whether any was.
bool LowerMasses(const Signals& s, std::array<Equation, 2>& eq, nlohmann::json& warnings) {
  bool lowered = false;
  for (Equation& e : eq) {
    if (e.mass_basis.size() < 2) continue;
    double least = INFINITY;
    for (Eigen::Index k = 0; k < s.t.size(); ++k)
      least = std::min(least, Combination(e.mass_basis, e.mass, s.x[0](k), s.x[1](k)));
    if (least > 0.0) continue;
    warnings.push_back("m_" + e.state + " lowered to " + e.mass_basis.front().Text("U", "r") +
                       ": on " + BasisText(e.mass_basis) + " it reached " + FormatNumber(least) +
                       " over the data");
    e.mass_basis = {e.mass_basis.front()};
    e.mass = Eigen::VectorXd::Zero(1);
    lowered = true;
  }
  if (lowered) SetTermNames(eq);
  return lowered;
}

// The transient runs split where a stretch begins: no run crosses a join.
std::vector<Span> SplitAtJoins(const std::vector<Span>& runs,
                               const std::vector<Eigen::Index>& joins) {
  std::vector<Span> out;
  for (Span run : runs) {
    for (const Eigen::Index j : joins)
      if (j > run.first && j <= run.last) {
        if (j - 1 > run.first) out.push_back({run.first, j - 1});
        run.first = j;
      }
    if (run.last > run.first) out.push_back(run);
  }
  return out;
}

}  // namespace

EbLrIdentification IdentifyWithEbLr(const Dataset& data, const std::string& speed,
                                    const std::string& rate, const std::string& thrust_input,
                                    const std::string& yaw_input, const EbLrOptions& options) {
  return IdentifyWithEbLr(data, {Stretch{0, data.rows()}}, speed, rate, thrust_input, yaw_input,
                          options);
}

EbLrIdentification IdentifyWithEbLr(const Dataset& data, const std::vector<Stretch>& stretches,
                                    const std::string& speed, const std::string& rate,
                                    const std::string& thrust_input, const std::string& yaw_input,
                                    const EbLrOptions& options) {
  CheckOptions(options);
  Signals s;
  s.t = data.t();
  s.x = {Column(data, speed, "speed"), Column(data, rate, "rate")};
  s.u = {Column(data, thrust_input, "thrust input"), Column(data, yaw_input, "yaw input")};
  const double dt = UniformStep(s.t, stretches);
  std::vector<Eigen::Index> joins;
  for (size_t k = 1; k < stretches.size(); ++k) joins.push_back(stretches[k].first);
  std::array<Equation, 2> eq = NewEquations(speed, rate, thrust_input, yaw_input, options);
  if (eq[0].thrust_loss_term) {
    s.q = Column(data, options.thrust_loss_channel, "thrust loss");
    eq[0].thrust_loss_text = options.thrust_loss_channel + "*" + speed;
  }
  const std::array<Eigen::VectorXd, 2> held = HeldInputs(data, options, s.u);
  CheckHeldInputs(held, eq, options);
  std::vector<Eigen::Index> breaks;
  for (const Stretch& st : stretches)
    for (const Eigen::Index b :
         StepBreaks({held[0].segment(st.first, st.rows()), held[1].segment(st.first, st.rows())},
                    options.steady.input_tolerance))
      breaks.push_back(st.first + b);
  SmoothStates(dt, stretches, breaks, s, eq);

  const SteadyWindowReport steady =
      DetectSteadyWindows(s.t, {s.x[0], s.x[1]}, {held[0], held[1]}, options.steady, joins);
  const std::vector<Span>& windows = steady.windows;
  EbLrIdentification out;
  nlohmann::json& info = out.details;
  info["warnings"] = nlohmann::json::array();
  if (options.lower_order) {
    CheckAnyWindow(windows, eq, options);
    for (int i = 0; i < 2; ++i) ChooseSigmaTerms(s, windows, eq[i], info["warnings"]);
    SetTermNames(eq);
  } else {
    CheckWindows(windows, eq);
  }
  const std::vector<Span> runs = SplitAtJoins(
      TransientRuns(s.t.size(), windows,
                    static_cast<Eigen::Index>(std::round(options.transient_margin_s / dt))),
      joins);
  const std::vector<Span> pieces = TransientPieces(
      runs, std::max<Eigen::Index>(
                1, static_cast<Eigen::Index>(std::round(options.transient_window_s / dt))));
  CheckPieces(pieces, eq);
  FitEquations(s, windows, runs, pieces, options, eq);
  if (options.lower_order && LowerMasses(s, eq, info["warnings"]))
    FitEquations(s, windows, runs, pieces, options, eq);

  info["steady_windows"] = WindowsJson(s, windows, eq);
  info["input_stretches"] = steady.stretches;
  info["windows_refused_drifting_input"] = steady.drifting;
  if (options.steady.full_turn_state >= 0) info["windows_full_turn"] = steady.full_turns;
  info["transient_runs"] = runs.size();
  info["transient_pieces"] = pieces.size();
  info["refinements"] = options.refinements;
  info["mass_fit"] = options.output_error_mass ? "output error" : "equation error";
  if (stretches.size() > 1) info["records"] = stretches.size();
  for (int i = 0; i < 2; ++i) {
    ReportEquation(eq[i], steady.noise_sd[i], s, options.output_error_mass, speed, rate, out);
    if (eq[i].sigma_from_transients) info["fit"]["sigma_" + eq[i].state]["from"] = "transients";
  }
  return out;
}

}  // namespace usvid::eb_lr
