#include "diagnosis/residual_discovery.h"

#include <cmath>

#include "methods/gp/gp_identify.h"
#include "methods/sindy/sindy.h"
#include "metrics/fit_metrics.h"
#include "preprocessing/pipeline.h"

namespace usvid::diagnosis {
namespace {

constexpr double kMinHeldoutR2 = 0.3;

// Explained share of the residual's mean square, not of its variance: the nominal model's
// error is d_s itself, and a missing constant force is all mean.
double ExplainedShare(const Eigen::VectorXd& d, const Eigen::VectorXd& prediction) {
  return d.squaredNorm() > 0 ? 1.0 - (d - prediction).squaredNorm() / d.squaredNorm() : 0.0;
}

// GP-SR on the residual: a small seeded search per state, the best of each search kept (no
// simulation: these are parts of derivatives, not models).
gp::GpIdentification GpOnResidual(const PreparedData& train, const std::vector<std::string>& states,
                                  const std::vector<std::string>& inputs) {
  gp::GpIdentifyOptions g;
  g.search.functions = gp::ParseOperators("+,-,*,abs");
  g.search.population = 300;
  g.search.generations = 20;
  g.search.restarts = 0;
  g.search.seed = 1;
  g.validation_fraction = 0.0;
  g.weight_fit = gp::WeightFit::kEquation;
  return gp::IdentifyWithGp(train, states, states, inputs, g);
}

bool IsKinematic(const std::string& s) {
  return s == "north" || s == "east" || s == "psi" || s == "chi" || s == "x";
}

}  // namespace

std::vector<DiscoveredTerms> DiscoverMissingTerms(const Dataset& data, const VesselSimulator& sim,
                                                  const EffectFitter& fitter,
                                                  const std::vector<double>& params,
                                                  const MeasuredData& measured) {
  const VesselInfo& info = sim.Info();
  std::vector<std::string> dynamic, measured_states;
  for (const std::string& c : measured.channels) {
    measured_states.push_back(c);
    if (!IsKinematic(c)) dynamic.push_back(c);
  }
  if (dynamic.empty()) return {};
  PreparedData prepared =
      Preprocess(data, measured_states, info.InputsIn(data), PreprocessOptions{});
  Dataset& p = prepared.data;
  const Eigen::Index n = p.rows();

  // The nominal derivative at the smoothed measured states (unmeasured ones from the nominal
  // free run at the nearest earlier row) and the inputs.
  const size_t states = info.states.size();
  std::vector<Eigen::VectorXd> residual(dynamic.size(), Eigen::VectorXd(n));
  std::vector<double> x(states), u(info.inputs.size()), dx(states);
  Eigen::Index row = 0;
  for (Eigen::Index k = 0; k < n; ++k) {
    const double t = p.t()(k);
    while (row + 1 < measured.rows() && measured.times[row + 1] <= t) ++row;
    for (size_t i = 0; i < states; ++i)
      x[i] = p.Has(info.states[i]) ? p[info.states[i]](k) : measured.fallback_states(row, i);
    for (size_t i = 0; i < info.inputs.size(); ++i)
      u[i] = p.Has(info.inputs[i]) ? p[info.inputs[i]](k) : info.actuation.neutral[i];
    fitter.Derivative(params, x.data(), u.data(), dx.data());
    for (size_t j = 0; j < dynamic.size(); ++j) {
      const int s = info.StateIndex(dynamic[j]);
      residual[j](k) = p[dynamic[j] + "_dot"](k) - dx[s];
    }
  }
  for (size_t j = 0; j < dynamic.size(); ++j) p.Set(dynamic[j] + "_dot", residual[j]);
  std::vector<std::string> inputs = info.CommandedInputs();
  if (measured.heading_channel >= 0) {
    // Named by their expressions, so that a proposed term is an expression in channel names
    // (a missing_term candidate, docs/diagnose.md).
    const std::string heading = measured.channels[measured.heading_channel];
    const std::string cos_name = "cos(" + heading + ")", sin_name = "sin(" + heading + ")";
    p.Set(cos_name, p[heading].array().cos().matrix());
    p.Set(sin_name, p[heading].array().sin().matrix());
    inputs.push_back(cos_name);
    inputs.push_back(sin_name);
  }

  // Train on the first part, judge on the held-out part (the same split as the effects).
  const double split_t = measured.times[measured.heldout.begin];
  std::vector<bool> train(n), held(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    train[k] = p.t()(k) < split_t;
    held[k] = !train[k];
  }
  PreparedData train_data = prepared;
  train_data.data.KeepRows(train);
  Dataset held_data = p;
  held_data.KeepRows(held);
  sindy::SindyOptions options;
  const sindy::SindyIdentification id =
      sindy::IdentifyWithSindy(train_data, dynamic, dynamic, inputs, options);

  const gp::GpIdentification gp_id = GpOnResidual(train_data, dynamic, inputs);

  std::vector<DiscoveredTerms> out;
  for (const std::string& s : dynamic) {
    const Eigen::VectorXd& d = held_data[s + "_dot"];
    const double r2 = ExplainedShare(
        d, sindy::PredictWithSindy(id, s, held_data, dynamic, inputs, options.library));
    if (r2 >= kMinHeldoutR2) out.push_back({s, id.equations[s].get<std::string>(), r2, std::string(sindy::kMethodName)});
    const std::string expression = gp_id.equations[s].get<std::string>();
    const Eigen::VectorXd prediction = Expression::Parse(expression).Evaluate(held_data);
    const double gp_r2 = prediction.allFinite() ? ExplainedShare(d, prediction) : 0.0;
    if (gp_r2 >= kMinHeldoutR2) out.push_back({s, expression, gp_r2, std::string(gp::kMethodName)});
  }
  return out;
}

}  // namespace usvid::diagnosis
