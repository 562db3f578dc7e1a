#include "metrics/equation_model.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/model_view.h"

namespace usvid {

EquationModel::EquationModel(const nlohmann::json& model,
                             const std::function<bool(const std::string&)>& has_channel) {
  const ModelView view(model);
  for (const auto& [state, text] : view.Equations()) {
    channels_.push_back(state);
    equations_.push_back(Expression::Parse(text, "model: equation for " + state));
  }
  auto has = [&](const std::string& s) {
    return std::ranges::find(channels_, s) != channels_.end();
  };
  // A kinematic state with its own equation is integrated by that equation, once.
  const bool kinematic_equation = has("psi") || has("chi") || has("north") || has("east");
  if (has("u") && has("v") && has("r") && has_channel("psi") && !kinematic_equation) {
    kinematics_ = Kinematics::kBody;
    for (const char* s : {"psi", "north", "east"}) channels_.push_back(s);
  } else if (has("U") && has("r") && has_channel("chi") && !kinematic_equation) {
    kinematics_ = Kinematics::kSpeedCourse;
    for (const char* s : {"chi", "north", "east"}) channels_.push_back(s);
  } else if (has("v") && has_channel("x") && !has("x")) {
    kinematics_ = Kinematics::kMsd;
    channels_.push_back("x");
  } else if (has("r") && has_channel("psi") && !has("psi")) {
    kinematics_ = Kinematics::kHeading;
    channels_.push_back("psi");
  }
  psi_ = Index("psi"), chi_ = Index("chi"), north_ = Index("north"), east_ = Index("east");
  u_ = Index("u"), v_ = Index("v"), r_ = Index("r"), speed_ = Index("U"), x_ = Index("x");
  for (const Expression& e : equations_) {
    std::vector<Source> sources;
    for (const std::string& name : e.Variables()) {
      if (has(name)) {
        sources.push_back({Index(name), -1});
        continue;
      }
      auto it = std::ranges::find(inputs_, name);
      if (it == inputs_.end()) it = inputs_.insert(inputs_.end(), name);
      sources.push_back({-1, static_cast<int>(it - inputs_.begin())});
    }
    sources_.push_back(std::move(sources));
  }
  delay_s_ = view.DelaySeconds();
  const auto n = static_cast<Eigen::Index>(channels_.size());
  k1_.resize(n), k2_.resize(n), k3_.resize(n), k4_.resize(n);
}

int EquationModel::Index(const std::string& channel) const {
  const auto it = std::ranges::find(channels_, channel);
  return it == channels_.end() ? -1 : static_cast<int>(it - channels_.begin());
}

void EquationModel::Derivative(const Eigen::VectorXd& x, const Eigen::VectorXd& u,
                               Eigen::VectorXd& dx) const {
  for (size_t e = 0; e < equations_.size(); ++e) {
    vars_.clear();
    for (const Source& s : sources_[e]) vars_.push_back(s.state >= 0 ? x(s.state) : u(s.input));
    dx(static_cast<Eigen::Index>(e)) = equations_[e].Evaluate(vars_);
  }
  switch (kinematics_) {
    case Kinematics::kBody:
      dx(psi_) = x(r_);
      dx(north_) = x(u_) * std::cos(x(psi_)) - x(v_) * std::sin(x(psi_));
      dx(east_) = x(u_) * std::sin(x(psi_)) + x(v_) * std::cos(x(psi_));
      break;
    case Kinematics::kSpeedCourse:
      dx(chi_) = x(r_);
      dx(north_) = x(speed_) * std::cos(x(chi_));
      dx(east_) = x(speed_) * std::sin(x(chi_));
      break;
    case Kinematics::kMsd:
      dx(x_) = x(v_);
      break;
    case Kinematics::kHeading:
      dx(psi_) = x(r_);
      break;
    case Kinematics::kNone:
      break;
  }
}

void EquationModel::Step(const Eigen::VectorXd& u, double h, Eigen::VectorXd& x) const {
  Derivative(x, u, k1_);
  Derivative(x + 0.5 * h * k1_, u, k2_);
  Derivative(x + 0.5 * h * k2_, u, k3_);
  Derivative(x + h * k3_, u, k4_);
  x += h / 6.0 * (k1_ + 2 * k2_ + 2 * k3_ + k4_);
}

void EquationModel::Derivatives(const Eigen::ArrayXXd& x, const Eigen::ArrayXXd& u,
                                Eigen::ArrayXXd& dx) const {
  const Eigen::Index rows = x.rows();
  dx.resize(rows, x.cols());
  for (size_t e = 0; e < equations_.size(); ++e) {
    columns_.clear();
    for (const Source& s : sources_[e])
      columns_.push_back(s.state >= 0 ? x.col(s.state).data() : u.col(s.input).data());
    equations_[e].EvaluateColumns(columns_, rows, dx.col(static_cast<Eigen::Index>(e)).data());
  }
  // The kinematics as Derivative() writes them, element by element.
  for (Eigen::Index j = 0; j < rows; ++j) {
    switch (kinematics_) {
      case Kinematics::kBody:
        dx(j, psi_) = x(j, r_);
        dx(j, north_) = x(j, u_) * std::cos(x(j, psi_)) - x(j, v_) * std::sin(x(j, psi_));
        dx(j, east_) = x(j, u_) * std::sin(x(j, psi_)) + x(j, v_) * std::cos(x(j, psi_));
        break;
      case Kinematics::kSpeedCourse:
        dx(j, chi_) = x(j, r_);
        dx(j, north_) = x(j, speed_) * std::cos(x(j, chi_));
        dx(j, east_) = x(j, speed_) * std::sin(x(j, chi_));
        break;
      case Kinematics::kMsd:
        dx(j, x_) = x(j, v_);
        break;
      case Kinematics::kHeading:
        dx(j, psi_) = x(j, r_);
        break;
      case Kinematics::kNone:
        break;
    }
  }
}

void EquationModel::Steps(const Eigen::ArrayXXd& u, const Eigen::ArrayXd& h,
                          const std::vector<bool>& advance, Eigen::ArrayXXd& x) const {
  // Step()'s operations in Step()'s order, per row: x + (0.5 h) k1, ..., then
  // x + (h / 6) (((k1 + 2 k2) + 2 k3) + k4).
  const auto stage = [&](const Eigen::ArrayXXd& k, double factor) {
    batch_at_.resize(x.rows(), x.cols());
    for (Eigen::Index j = 0; j < x.rows(); ++j) {
      const double step = factor * h(j);
      batch_at_.row(j) = x.row(j) + step * k.row(j);
    }
  };
  Derivatives(x, u, batch_k1_);
  stage(batch_k1_, 0.5);
  Derivatives(batch_at_, u, batch_k2_);
  stage(batch_k2_, 0.5);
  Derivatives(batch_at_, u, batch_k3_);
  stage(batch_k3_, 1.0);
  Derivatives(batch_at_, u, batch_k4_);
  for (Eigen::Index j = 0; j < x.rows(); ++j) {
    if (!advance[static_cast<size_t>(j)]) continue;
    const double sixth = h(j) / 6.0;
    x.row(j) +=
        sixth * (batch_k1_.row(j) + 2 * batch_k2_.row(j) + 2 * batch_k3_.row(j) + batch_k4_.row(j));
  }
}

}  // namespace usvid
