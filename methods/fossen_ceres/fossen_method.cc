// `fossen-ceres`: the parametric Fossen 3-DOF fit (methods/fossen_ceres/fossen_fit.h) on
// forces, a waterjet or a rudder-propeller input map, or the jets' forces; registered in
// methods/method_list.h.
#include <algorithm>
#include <array>
#include <cmath>
#include <type_traits>

#include "core/error.h"
#include "methods/channel_fit.h"
#include "methods/fossen_ceres/fossen_fit.h"
#include "methods/fossen_ceres/fossen_models.h"
#include "methods/fossen_ceres/jet_force_model.h"
#include "methods/method.h"
#include "preprocessing/delay_estimation.h"
#include "simulation/segment_error.h"
#include "simulation/vessel_simulator.h"
#include "simulators/odin3dof.h"

namespace usvid {
namespace {

// fossen-ceres: a parametric Fossen 3-DOF model (odin3dof's, the same driven through the
// waterjet or the rudder-propeller input map, or the high-speed form on the jets' forces),
// equation error then multiple shooting.
template <typename Model>
nlohmann::json IdentifyFossen(const IdentifyRequest& request, const MethodOptions& o,
                              const Dataset& data, const PreparedData& prepared, const Logger& log,
                              std::vector<double> start = {}) {
  constexpr bool kOdin3Dof = std::is_same_v<Model, fossen::Odin3DofModel>;
  fossen::FossenOptions fo;
  fo.start = std::move(start);
  fo.segment_s = o.Number("segment_s");
  fo.robust = o.Flag("robust");
  fo.max_rows = o.Integer("fit_rows");
  const std::string fit_mode = o.Text("fit");
  if (fo.max_rows > 0 && prepared.data.rows() > fo.max_rows)
    Log(log, "fitting " + std::to_string(fo.max_rows) + " of " +
                 std::to_string(prepared.data.rows()) +
                 " rows, spread over the record (--fit-rows)");
  // One thread for Ceres: its parallel evaluation sums the cost in a thread-dependent order, and
  // the last digits of the fit would differ between 1 and 2 threads.
  fo.threads = 1;
  const auto eq = fossen::FitEquationErrorFor<Model>(prepared, fo);
  Log(log, "equation-error fit: " + eq.termination);
  auto fit = eq;
  if (fit_mode == "simulation") {
    fit = fossen::FitSimulationErrorFor<Model>(prepared, eq.params, fo);
    Log(log, "simulation-error fit (multiple shooting): " + fit.termination);
  }
  nlohmann::json params = nlohmann::json::object(), sd = nlohmann::json::object(),
                 eq_params = nlohmann::json::object();
  for (int i = 0; i < Model::kParams; ++i) {
    const std::string name(Model::kParamNames[i]);
    params[name] = fit.params[i];
    sd[name] = fit.sd[i];
    eq_params[name] = eq.params[i];
  }
  const nlohmann::json equations = fossen::EquationsFor<Model>(fit.params);
  nlohmann::json refined = nullptr;
  if (!kOdin3Dof && prepared.delay_estimate) {
    Log(log,
        "delay not refined: the " + std::string(Model::kName) + " model is no registered vessel");
  } else if (prepared.delay_estimate) {
    // The delay to a fraction of a sample: NLopt (DIRECT-L, then Sbplx) on the segmented
    // simulation error of the fitted model on the data as recorded.
    const VesselSimulator& sim = FindVessel(std::string(Odin3Dof::kName));
    const std::vector<double> p(fit.params.begin(), fit.params.end());
    auto cost = [&](const std::vector<double>& d) {
      EffectValues<double> e;
      e.delay_s = d[0];
      return SegmentedSimulationError(sim, p, e, data, {"u", "v", "r"}, fo.segment_s);
    };
    const DelayEstimate d =
        ContinuousDelay(cost, 1, request.preprocess.max_delay_s, {prepared.delay_s}, 60);
    refined = d.delay_s;
    Log(log, "delay refined on the simulation error: " + std::to_string(d.delay_s) + " s");
  }
  return {{"parameters", params},
          {"equations", equations},
          {"fossen",
           {{"model", std::string(Model::kName)},
            {"fit", fit_mode},
            {"segment_s", fo.segment_s},
            {"fit_rows", fo.max_rows},
            {"rows_fitted", fit.rows},
            {"robust", fo.robust},
            {"parameter_sd", sd},
            {"covariance_ok", fit.covariance_ok},
            {"termination", fit.termination},
            {"converged", fit.converged},
            {"initial_cost", fit.initial_cost},
            {"final_cost", fit.final_cost},
            {"iterations", fit.iterations},
            {"equation_error_parameters", eq_params},
            {"delay_refined_s", refined}}}};
}

const std::vector<std::string> kForces = {"tau_x", "tau_y", "tau_n"},
                               kJetForces = {"tau_x", "tau_y", "tau_n", "jet_flow"},
                               kWaterjets = {"throttle", "nozzle", "bucket"},
                               kRudder = {"delta", "rev"}, kRudderRps = {"delta", "n"};

// RudderRpsModel's starting values for a vessel file's ship: RudderModel's (KVLCC2, 320 m, at
// 15.5 kn) scaled by Froude's law to the ship's length L (lambda = L / 320): masses lambda^3,
// inertia lambda^5, linear damping lambda^2.5 (force) and lambda^3.5, lambda^4.5 (moment),
// quadratic lambda^2 and lambda^5, the propeller's gains lambda^4 and lambda^5 (n ~ lambda^-0.5);
// times the water's density over sea water's. The rudder's terms take the file's sign.
std::vector<double> RudderRpsStart(const VesselInfo& info) {
  const auto param = [&](const std::string& name) {
    return info.default_params.at(std::find(info.params.begin(), info.params.end(), name) -
                                  info.params.begin());
  };
  const double lambda = info.length_m / 320.0, density = param("rho") / 1025.0;
  constexpr std::array<double, 13> kExponent = {3, 3, 5, 2.5, 2, 2.5, 2, 3.5, 4.5, 5, 4, 4, 5};
  std::vector<double> start(13);
  for (int i = 0; i < 13; ++i)
    start[i] = fossen::RudderModel::kStart[i] * density * std::pow(lambda, kExponent[i]);
  // RudderModel: tau_y = Ty n^2 delta, tau_n = -Tn n^2 delta with an ITTC rudder (a positive
  // angle turns to port); here both signs are the fit's, starting from the file's rudder sign.
  const double sign = info.actuation.yaw_sign;  // +1: MMG, -1: ITTC
  start[fossen::RudderRpsModel::kTy] *= -sign;
  start[fossen::RudderRpsModel::kTn] *= sign;
  return start;
}

nlohmann::json IdentifyFossenModel(const Dataset& data, const IdentifyRequest& request,
                                   const MethodOptions& o, const Logger& log) {
  const Channels c = DefaultChannels(request);
  const bool file_ship =
      c.inputs == kRudderRps && !request.vessel.empty() && request.vessel.Info().type == "mmg";
  if (c.states != std::vector<std::string>{"u", "v", "r"} ||
      (c.inputs != kForces && c.inputs != kJetForces && c.inputs != kWaterjets &&
       c.inputs != kRudder && !file_ship))
    throw InputError(
        "--method fossen-ceres: fits the Fossen 3-DOF model, states u,v,r with inputs "
        "tau_x,tau_y,tau_n (--vessel odin3dof), tau_x,tau_y,tau_n,jet_flow with speed-dependent "
        "damping (--vessel odin-hs --forces waterjet), throttle,nozzle,bucket through a "
        "waterjet map (--vessel odin-hs) or delta,rev through a rudder-propeller map (--vessel "
        "kvlcc2), or delta,n through the same for a vessel file's ship (--vessel SHIP.yaml)");
  ChannelFit fit = PrepareChannelFit(data, request, c, log);
  const std::vector<std::string>& inputs = fit.channels.inputs;
  if (inputs == kJetForces)
    fit.model.update(IdentifyFossen<fossen::JetForceModel>(request, o, data, fit.prepared, log));
  else if (inputs == kWaterjets)
    fit.model.update(IdentifyFossen<fossen::WaterjetModel>(request, o, data, fit.prepared, log));
  else if (inputs == kRudder)
    fit.model.update(IdentifyFossen<fossen::RudderModel>(request, o, data, fit.prepared, log));
  else if (inputs == kRudderRps)
    fit.model.update(IdentifyFossen<fossen::RudderRpsModel>(request, o, data, fit.prepared, log,
                                                            RudderRpsStart(request.vessel.Info())));
  else
    fit.model.update(IdentifyFossen<fossen::Odin3DofModel>(request, o, data, fit.prepared, log));
  SetTrain(fit, request);
  return fit.model;
}

}  // namespace

Method FossenCeresMethod() {
  Method m;
  m.name = std::string(fossen::kMethodName);
  m.summary = "parametric Fossen 3-DOF, Ceres: forces, or a waterjet or rudder input map";
  m.options = {
      ChoiceOption("fit", "simulation", {"simulation", "equation"},
                   "simulation error (multiple shooting, after an equation-error start) or "
                   "equation error alone"),
      NumberOption("segment_s", 10.0, 0, kUnbounded, "shooting segment length [s]",
                   /*min_exclusive=*/true),
      FlagOption("robust", "Huber loss on the residuals"),
      IntegerOption("fit_rows", kCeresFitRows, 0, kUnbounded,
                    "the most rows the Ceres fits use, spread over a longer record (0: all)"),
  };
  m.identify = IdentifyFossenModel;
  m.channel_inputs = true;
  m.relative_cost = 10.0;  // the multiple-shooting fit
  return m;
}

}  // namespace usvid
