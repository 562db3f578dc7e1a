#include "metrics/free_run.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/error.h"
#include "effects/effect.h"
#include "effects/effect_values.h"
#include "methods/expression.h"
#include "simulation/vessel_simulator.h"

namespace usvid {
namespace {

// u(t - delay) under zero-order hold on the data's stamps (the first value before the start).
double HeldInput(const Dataset& d, const Eigen::VectorXd& u, double t) {
  const Eigen::VectorXd& ts = d.t();
  const auto* it = std::upper_bound(ts.data(), ts.data() + ts.size(), t);
  const Eigen::Index k = std::max<Eigen::Index>(0, (it - ts.data()) - 1);
  return u(k);
}

// A vessel model: the registered simulator with the model's parameters and effects.
FreeRun FreeRunVessel(const nlohmann::json& model, const Dataset& data, double max_step) {
  if (!model.at("vessel").is_string()) throw InputError("model: \"vessel\" is not a string");
  const VesselSimulator& sim = FindVessel(model.at("vessel").get<std::string>());
  const VesselInfo& info = sim.Info();
  const std::vector<double> params =
      info.ParamsFrom(model.contains("parameters") ? model.at("parameters") : nlohmann::json());
  std::vector<Effect> effects;
  if (model.contains("effects")) {
    if (!model.at("effects").is_array()) throw InputError("model: \"effects\" is not an array");
    for (const auto& e : model.at("effects")) effects.push_back(EffectFromJson(e));
  }
  RunOptions options;
  options.dt = max_step;
  const SimulationResult result = sim.RunInputs(data, params, ValuesOf(effects), options);
  FreeRun run;
  run.diverged = result.diverged;
  run.diverged_at_s = result.diverged_at_s;
  run.simulated = Dataset(data.t());
  const Eigen::Index rows = result.data.rows();
  for (const std::string& state : info.states) {
    if (!data.Has(state) || !result.data.Has(state)) continue;
    // Past a divergence the last finite value is held, as for equation models.
    Eigen::VectorXd v(data.rows());
    const Eigen::VectorXd& sim_values = result.data[state];
    for (Eigen::Index k = 0; k < data.rows(); ++k)
      v(k) = rows > 0 ? sim_values(std::min(k, rows - 1)) : data[state](0);
    run.simulated.Set(state, v);
    run.channels.push_back(state);
  }
  if (run.channels.empty())
    throw InputError("data: none of vessel " + info.name + "'s states to compare with");
  return run;
}

}  // namespace

FreeRun FreeRunModel(const nlohmann::json& model, const Dataset& data, double max_step) {
  if (!model.contains("equations") && model.contains("vessel") && !model.at("vessel").is_null() &&
      model.at("vessel") != "")
    return FreeRunVessel(model, data, max_step);
  if (!model.contains("equations") || !model.at("equations").is_object() ||
      model.at("equations").empty())
    throw InputError("model: no \"equations\" object");
  // The integrated channels: the states with equations, then the kinematic ones.
  std::vector<std::string> channels;
  std::vector<Expression> equations;
  for (const auto& [state, text] : model.at("equations").items()) {
    if (!text.is_string()) throw InputError("model: equation for '" + state + "' is not a string");
    channels.push_back(state);
    equations.push_back(Expression::Parse(text.get<std::string>(), "model: equation for " + state));
  }
  auto has = [&](const std::string& s) {
    return std::find(channels.begin(), channels.end(), s) != channels.end();
  };
  enum class Kinematics { kNone, kBody, kSpeedCourse, kMsd, kHeading } kin = Kinematics::kNone;
  if (has("u") && has("v") && has("r") && data.Has("psi")) {
    kin = Kinematics::kBody;
    for (const char* s : {"psi", "north", "east"}) channels.push_back(s);
  } else if (has("U") && has("r") && data.Has("chi")) {
    kin = Kinematics::kSpeedCourse;
    for (const char* s : {"chi", "north", "east"}) channels.push_back(s);
  } else if (has("v") && data.Has("x") && !has("x")) {
    kin = Kinematics::kMsd;
    channels.push_back("x");
  } else if (has("r") && data.Has("psi") && !has("psi")) {
    kin = Kinematics::kHeading;  // a heading model (Nomoto): psi' = r
    channels.push_back("psi");
  }
  const int n = static_cast<int>(channels.size());
  auto index = [&](const std::string& s) {
    return static_cast<int>(std::find(channels.begin(), channels.end(), s) - channels.begin());
  };
  for (const std::string& c : channels)
    if (c != "north" && c != "east" && !data.Has(c))
      throw InputError("data: no channel '" + c + "' for the model's free run");

  // Each equation's variables: integrated channels, or inputs read from the data.
  struct Source {
    int state = -1;
    const Eigen::VectorXd* input = nullptr;
  };
  std::vector<std::vector<Source>> sources;
  for (const Expression& e : equations) {
    std::vector<Source> s;
    for (const std::string& v : e.Variables()) {
      if (has(v)) {
        s.push_back({index(v), nullptr});
      } else if (data.Has(v)) {
        s.push_back({-1, &data[v]});
      } else {
        throw InputError("data: no channel '" + v + "' used by the model");
      }
    }
    sources.push_back(std::move(s));
  }
  const double delay =
      model.contains("preprocessing") ? model["preprocessing"].value("delay_s", 0.0) : 0.0;

  Eigen::VectorXd x(n);
  double bound = 1e3;
  for (int i = 0; i < n; ++i) {
    const std::string& c = channels[i];
    x(i) = data.Has(c) && data.Get(c).sampled(0) ? data[c](0) : 0.0;
    if (data.Has(c)) bound = std::max(bound, 10.0 * data[c].cwiseAbs().maxCoeff());
  }
  std::vector<double> vars;
  auto derivative = [&](double t, const Eigen::VectorXd& s, Eigen::VectorXd& dx) {
    for (size_t e = 0; e < equations.size(); ++e) {
      vars.clear();
      for (const Source& src : sources[e])
        vars.push_back(src.state >= 0 ? s(src.state) : HeldInput(data, *src.input, t - delay));
      dx(static_cast<Eigen::Index>(e)) = equations[e].Evaluate(vars);
    }
    switch (kin) {
      case Kinematics::kBody: {
        const double psi = s(index("psi")), u = s(index("u")), v = s(index("v"));
        dx(index("psi")) = s(index("r"));
        dx(index("north")) = u * std::cos(psi) - v * std::sin(psi);
        dx(index("east")) = u * std::sin(psi) + v * std::cos(psi);
        break;
      }
      case Kinematics::kSpeedCourse: {
        const double chi = s(index("chi")), speed = s(index("U"));
        dx(index("chi")) = s(index("r"));
        dx(index("north")) = speed * std::cos(chi);
        dx(index("east")) = speed * std::sin(chi);
        break;
      }
      case Kinematics::kMsd:
        dx(index("x")) = s(index("v"));
        break;
      case Kinematics::kHeading:
        dx(index("psi")) = s(index("r"));
        break;
      case Kinematics::kNone:
        break;
    }
  };

  FreeRun run;
  run.channels = channels;
  const Eigen::Index rows = data.rows();
  Eigen::MatrixXd out(rows, n);
  out.row(0) = x.transpose();
  Eigen::VectorXd k1(n), k2(n), k3(n), k4(n);
  for (Eigen::Index k = 1; k < rows; ++k) {
    if (!run.diverged) {
      const double t0 = data.t()(k - 1), span = data.t()(k) - t0;
      const int steps = std::max(1, static_cast<int>(std::ceil(span / max_step - 1e-9)));
      const double h = span / steps;
      for (int s = 0; s < steps; ++s) {
        // The input is held at its value at the step's start (zero-order hold).
        const double t = t0 + s * h;
        derivative(t, x, k1);
        derivative(t, x + 0.5 * h * k1, k2);
        derivative(t, x + 0.5 * h * k2, k3);
        derivative(t, x + h * k3, k4);
        x += h / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4);
      }
      if (!x.allFinite() || x.cwiseAbs().maxCoeff() > bound) {
        run.diverged = true;
        run.diverged_at_s = data.t()(k);
        x = out.row(k - 1).transpose();
      }
    }
    out.row(k) = x.transpose();
  }
  run.simulated = Dataset(data.t());
  for (int i = 0; i < n; ++i) run.simulated.Set(channels[i], out.col(i));
  return run;
}

}  // namespace usvid
