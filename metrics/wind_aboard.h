// The logged wind an equation model meets on its own heading, in a free run
// (docs/model.md#wind-on-its-own-heading). A record's relative wind (wind_speed,
// wind_direction, and the body components wind_u, wind_v derived from them) is the true wind
// seen from the hull that logged it: its heading and velocities are in it, so read as logged it
// feeds the measured heading into the model's inputs. Here each row's relative wind is turned
// into the air's velocity over the ground (simulation/recorded_inputs.h, RecordedAirOverGround),
// and the model's wind inputs are made anew from it at every step, with the model's own heading
// and velocities (the record's where the model does not integrate them).
#pragma once

#include <Eigen/Core>
#include <array>
#include <string>
#include <utility>
#include <vector>

#include "core/dataset.h"

namespace usvid {

class WindAboard {
 public:
  // Engaged when `inputs` name a wind channel (wind_speed, wind_direction, wind_u, wind_v),
  // `data` logs wind_speed, wind_direction, psi, u and v, and `channels` (what the free run
  // integrates) hold psi.
  WindAboard(const Dataset& data, const std::vector<std::string>& inputs,
             const std::vector<std::string>& channels);
  bool engaged() const { return engaged_; }

  // The air over the ground on the record's rows [north, east], for the free run's zero-order
  // hold.
  const Eigen::VectorXd& air_north() const { return air_north_; }
  const Eigen::VectorXd& air_east() const { return air_east_; }
  // Where the model's own heading and velocities are among the channels; -1: the record's.
  int psi_channel() const { return psi_; }
  int u_channel() const { return u_; }
  int v_channel() const { return v_; }

  // Sets each wind input, set(index among the inputs, its value), to what the air [north, east]
  // makes over a hull heading psi with body velocities u, v. Called at every integration step:
  // it allocates nothing.
  template <typename Setter>
  void Set(double north, double east, double psi, double u, double v, Setter set) const {
    const std::array<double, 4> value = Values(north, east, psi, u, v);
    for (const auto& [input, kind] : wind_inputs_) set(input, value[kind]);
  }

 private:
  // wind_speed, wind_direction, wind_u, wind_v aboard.
  static std::array<double, 4> Values(double north, double east, double psi, double u, double v);

  bool engaged_ = false;
  int psi_ = -1, u_ = -1, v_ = -1;
  // Per wind input: its index among the inputs, and which of speed, direction, wind_u, wind_v.
  std::vector<std::pair<int, int>> wind_inputs_;
  Eigen::VectorXd air_north_, air_east_;
};

}  // namespace usvid
