// VesselSimulator for a compile-time vessel V: the one place where the runtime interface meets
// the templated dynamics.
#pragma once

#include <cmath>

#include "core/check.h"
#include "core/error.h"
#include "simulation/closed_loop.h"
#include "simulation/open_loop.h"
#include "simulation/recorded_inputs.h"
#include "simulation/vessel_simulator.h"

namespace usvid {

template <Vessel V>
class TypedVesselSimulator : public VesselSimulator {
 public:
  explicit TypedVesselSimulator(VesselInfo info) : info_(std::move(info)) {}
  const VesselInfo& Info() const override { return info_; }

  SimulationResult RunManeuver(Maneuver& maneuver, const std::vector<double>& params,
                               const EffectValues<double>& effects,
                               const RunOptions& options) const override {
    const auto p = ToArray<V::kParams>(params);
    const KinematicStates kinematic{info_.StateIndex("north"), info_.StateIndex("east"),
                                    info_.actuation.heading_state};
    std::array<double, V::kInputs> limits = NoLimits();
    if (effects.saturation_fraction > 0.0) {
      // The peak command comes from the same maneuver run without clipping: a copy of it, so that
      // the run itself starts where the maneuver does (a zig-zag at its approach, not reversed
      // where the probe left it).
      EffectValues<double> free = effects;
      free.saturation_fraction = 0.0;
      const std::unique_ptr<Maneuver> fresh = maneuver.Clone();
      const ClosedLoopRun probe = RunClosedLoop<V>(*fresh, p, free, limits, kinematic, options);
      limits = SaturationLimits<V::kInputs>(effects.saturation_fraction,
                                            ToArray<V::kInputs>(probe.commands.PeakAbs()),
                                            effects.saturation_inputs);
    }
    const ClosedLoopRun run = RunClosedLoop<V>(maneuver, p, effects, limits, kinematic, options);
    SimulationResult result;
    result.run_in_s = run.run_in_s;
    result.diverged = run.diverged;
    result.diverged_at_s = run.diverged ? run.times.back() : 0.0;
    result.maneuver = {{"spec", maneuver.Spec()}, {"report", maneuver.Report()}};
    result.data = MakeDataset(run.times, run.states, V::kStates, run.commands, effects);
    return result;
  }

  SimulationResult RunInputs(const Dataset& data, const std::vector<double>& params,
                             const EffectValues<double>& effects,
                             const RunOptions& options) const override {
    const InputTrack track = RecordedInputs(data, info_);
    std::array<double, Plant<V>::kStates> x0{};
    for (int i = 0; i < V::kStates; ++i) {
      const Channel* c = data.Find(info_.states[i]);
      if (c != nullptr && c->IsSampled(0)) x0[i] = c->Value(0);
    }
    Plant<V>::InitialLagState(track.At(data.t()(0)), x0.data());
    std::array<double, V::kInputs> limits = NoLimits();
    if (effects.saturation_fraction > 0.0)
      limits = SaturationLimits<V::kInputs>(effects.saturation_fraction,
                                            ToArray<V::kInputs>(track.PeakAbs()),
                                            effects.saturation_inputs);
    // A logged relative wind is the logged hull's: the free run makes its own from the air.
    std::optional<InputTrack> air;
    EffectValues<double> env = effects;
    if constexpr (Plant<V>::kWindOverGround) {
      air = WindOverGround(data, info_, track);
      env.wind_over_ground = air.has_value();
    }
    OpenLoopSetup setup;
    setup.inputs = air ? &*air : &track;
    setup.times.assign(data.t().data(), data.t().data() + data.rows());
    setup.max_step = options.dt;
    setup.integrator = options.integrator;
    std::vector<double> out(setup.times.size() * Plant<V>::kStates);
    const size_t rows = RolloutOpenLoop<V, double>(
        setup, x0.data(), ToArray<V::kParams>(params).data(), env, limits, out.data());
    SimulationResult result;
    result.diverged = rows < setup.times.size();
    result.diverged_at_s = result.diverged ? setup.times[rows] : 0.0;
    std::vector<double> states;
    for (size_t k = 0; k < rows; ++k)
      for (int i = 0; i < V::kStates; ++i) states.push_back(out[k * Plant<V>::kStates + i]);
    setup.times.resize(rows);
    result.data = MakeDataset(setup.times, states, V::kStates, track, effects);
    return result;
  }

  std::optional<double> Resistance(double speed, const std::vector<double>& params) const override {
    if constexpr (requires { V::template Resistance<double>(speed, params.data()); }) {
      return V::template Resistance<double>(speed, params.data());
    } else {
      return std::nullopt;
    }
  }

  std::optional<double> FroudeNumber(double speed) const override {
    if constexpr (requires { V::FroudeNumber(speed); }) {
      return V::FroudeNumber(speed);
    } else {
      // A vessel whose length is known only at run time (a vessel file).
      if (info_.length_m > 0) return speed / std::sqrt(9.81 * info_.length_m);
      return std::nullopt;
    }
  }

 private:
  template <int M>
  static std::array<double, M> ToArray(const std::vector<double>& v) {
    USVID_CHECK(static_cast<int>(v.size()) == M, "a vector of the vessel's size");
    std::array<double, M> a{};
    std::copy(v.begin(), v.end(), a.begin());
    return a;
  }

  static std::array<double, V::kInputs> NoLimits() {
    std::array<double, V::kInputs> limits;
    limits.fill(INFINITY);
    return limits;
  }

  // t, states (rate channel with the sensor bias), derived U and chi, inputs.
  Dataset MakeDataset(const std::vector<double>& times, const std::vector<double>& states,
                      int stride, const InputTrack& commands,
                      const EffectValues<double>& effects) const {
    const auto n = static_cast<Eigen::Index>(times.size());
    Dataset d(Eigen::Map<const Eigen::VectorXd>(times.data(), n));
    Eigen::MatrixXd x(n, V::kStates);
    for (Eigen::Index k = 0; k < n; ++k)
      for (int i = 0; i < V::kStates; ++i) x(k, i) = states[k * stride + i];
    x.col(V::kRateState).array() += effects.sensor_bias;
    for (int i = 0; i < V::kStates; ++i) d.Set(info_.states[i], x.col(i));
    if constexpr (requires { V::kDerivesSpeedAndCourse; }) {
      const Eigen::VectorXd u = x.col(info_.StateIndex("u")), v = x.col(info_.StateIndex("v"));
      const Eigen::VectorXd psi = x.col(info_.StateIndex("psi"));
      Eigen::VectorXd speed(n), course(n);
      for (Eigen::Index k = 0; k < n; ++k) {
        speed(k) = std::hypot(u(k), v(k));
        course(k) = psi(k) + std::atan2(v(k), u(k));
      }
      d.Set("U", speed);
      d.Set("chi", course);
    }
    for (int i = 0; i < V::kInputs; ++i) {
      if (info_.IsMeasuredInput(i) && !info_.wind_body) continue;  // no body for the wind
      Eigen::VectorXd c(n);
      for (Eigen::Index k = 0; k < n; ++k) c(k) = commands.At(times[k])[i];
      d.Set(info_.inputs[i], c);
    }
    return d;
  }

  VesselInfo info_;
};

}  // namespace usvid
