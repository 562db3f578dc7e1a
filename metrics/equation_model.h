// A model written as equations (model.json "equations": one right-hand side per identified
// state) as a system that can be stepped: the identified states, then the known kinematics of
// the states without an equation,
//   body velocities u, v, r:  psi' = r, north' = u cos psi - v sin psi, east' = u sin psi + v cos psi
//   speed and turn U, r:      chi' = r, north' = U cos chi, east' = U sin chi
//   msd velocity v:           x' = v
//   a rate of turn r alone:   psi' = r   (a heading model: Nomoto)
// and its inputs: every variable of an equation that is not one of those states. The free run
// (free_run.h) steps it under the data's inputs, the closed-loop replay (closed_loop_replay.h)
// under the commands of a maneuver that watches its states.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/expression.h"

namespace usvid {

class EquationModel {
 public:
  // `has_channel` says which channels the data offer: a kinematic state is integrated only when
  // the data have it to start from (psi for body velocities, chi for U and r, x for msd, psi for
  // a heading model). Throws InputError for a model without an "equations" object or an
  // equation that does not parse.
  EquationModel(const nlohmann::json& model, const std::function<bool(const std::string&)>& has_channel);

  // The integrated channels: the states with equations, then the kinematic ones.
  const std::vector<std::string>& Channels() const { return channels_; }
  // The variables the equations read that are not integrated channels, in a fixed order.
  const std::vector<std::string>& Inputs() const { return inputs_; }
  // The input delay the model was identified with (preprocessing delay_s) [s].
  double DelayS() const { return delay_s_; }
  int Index(const std::string& channel) const;  // -1 when not integrated

  // dx/dt at state x under inputs u (in Inputs() order).
  void Derivative(const Eigen::VectorXd& x, const Eigen::VectorXd& u, Eigen::VectorXd& dx) const;
  // One classical Runge-Kutta step of length h with the inputs held (zero-order hold).
  void Step(const Eigen::VectorXd& u, double h, Eigen::VectorXd& x) const;

  // Many states side by side, one row each: x has a column per channel (Channels()), u per input
  // (Inputs()); dx receives x's shape. Each equation is evaluated an operator at a time over all
  // rows (Expression::EvaluateColumns), bit-identical to Derivative() row by row.
  void Derivatives(const Eigen::ArrayXXd& x, const Eigen::ArrayXXd& u, Eigen::ArrayXXd& dx) const;
  // Step() for every row whose `advance` is set, each with its own h; the other rows are left as
  // they are. Bit-identical to Step() row by row.
  void Steps(const Eigen::ArrayXXd& u, const Eigen::ArrayXd& h, const std::vector<bool>& advance,
             Eigen::ArrayXXd& x) const;

 private:
  enum class Kinematics { kNone, kBody, kSpeedCourse, kMsd, kHeading };
  struct Source {
    int state = -1, input = -1;
  };
  std::vector<std::string> channels_, inputs_;
  std::vector<Expression> equations_;
  std::vector<std::vector<Source>> sources_;  // per equation, per variable
  Kinematics kinematics_ = Kinematics::kNone;
  int psi_ = -1, chi_ = -1, north_ = -1, east_ = -1, u_ = -1, v_ = -1, r_ = -1, speed_ = -1,
      x_ = -1;
  double delay_s_ = 0.0;
  mutable std::vector<double> vars_;
  mutable Eigen::VectorXd k1_, k2_, k3_, k4_;
  mutable Eigen::ArrayXXd batch_k1_, batch_k2_, batch_k3_, batch_k4_, batch_at_;
  mutable std::vector<const double*> columns_;
};

}  // namespace usvid
