#include "simulation/vessel_file.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <numbers>
#include <optional>
#include <set>

#include "core/error.h"
#include "core/parse_number.h"
#include "core/yaml_section.h"
#include "simulation/mmg_estimates.h"
#include "simulation/wind_estimates.h"
#include "simulators/mmg.h"

namespace usvid {

namespace {

// The hull's section: the main particulars into `h`, the yaw inertia as given (k_zz or I_zG).
struct YawInertia {
  std::optional<double> k_zz, I_zG;
};
YawInertia ReadHull(YamlSection& top, MmgHull& h) {
  YamlSection hull = top.RequiredChild("hull", "the main particulars");
  h.L = hull.Positive("L", "length between perpendiculars [m]");
  h.B = hull.Positive("B", "breadth [m]");
  h.d = hull.Positive("d", "draft [m]");
  h.C_b = hull.Positive("C_b", "block coefficient");
  if (h.C_b > 1.0)
    hull.FailKey("C_b", "a block coefficient is at most 1, got " + FormatNumber(h.C_b));
  h.mass = hull.Positive("mass", "displacement mass [kg]");
  h.x_G = hull.Required("x_G", "centre of gravity ahead of midship [m]");
  YawInertia yaw{hull.Number("k_zz"), hull.Number("I_zG")};
  if (!yaw.k_zz && !yaw.I_zG)
    hull.FailHere("k_zz: missing (the yaw radius of gyration / L; or give I_zG [kg m^2])");
  if (yaw.k_zz && yaw.I_zG) hull.FailKey("I_zG", "give k_zz or I_zG, not both");
  if ((yaw.k_zz && *yaw.k_zz <= 0) || (yaw.I_zG && *yaw.I_zG <= 0))
    hull.FailKey(yaw.k_zz ? "k_zz" : "I_zG", "must be above 0");
  hull.RefuseUnknown();
  return yaw;
}

// The controls' section: the rudder's sign and range, the propeller's revolutions.
struct Controls {
  std::string sign;
  double rudder_max_deg = 0.0, rudder_rate_deg_s = 0.0, n_min = 0.0, n_max = 0.0, n_cruise = 0.0;
};
Controls ReadControls(YamlSection& top) {
  YamlSection ctl = top.RequiredChild("controls", "the rudder's sign and range, the propeller's");
  Controls c;
  c.sign = ctl.Text("rudder_sign").value_or("");
  if (c.sign != "mmg" && c.sign != "ittc")
    ctl.FailKey("rudder_sign", "give mmg (a positive delta turns to starboard) or ittc (to port)");
  c.rudder_max_deg = ctl.Positive("rudder_max_deg", "hard over [deg]");
  if (c.rudder_max_deg > 90) ctl.FailKey("rudder_max_deg", "at most 90 deg");
  c.rudder_rate_deg_s = ctl.Number("rudder_rate_deg_s").value_or(0.0);
  if (c.rudder_rate_deg_s < 0) ctl.FailKey("rudder_rate_deg_s", "must be 0 (no limit) or above");
  c.n_max = ctl.Positive("n_max", "highest propeller revolutions ahead [1/s]");
  c.n_min = ctl.Number("n_min").value_or(0.0);
  c.n_cruise = ctl.Positive("n_cruise", "propeller revolutions of a cruise [1/s]");
  if (c.n_min > c.n_cruise || c.n_cruise > c.n_max)
    ctl.FailKey("n_cruise", "must lie between n_min " + FormatNumber(c.n_min) + " and n_max " +
                                FormatNumber(c.n_max));
  ctl.RefuseUnknown();
  return c;
}

// The body above the water (Fujiwara et al. 1998's inputs), when the file has a wind section.
struct WindPart {
  bool present = false;
  WindBody body;
  double rho_air = 1.22;
  bool in_model = false;
};
WindPart ReadWind(YamlSection& top, const MmgHull& h) {
  WindPart w;
  std::optional<YamlSection> wind = top.Child("wind");
  if (!wind) return w;
  w.present = true;
  WindBody& body = w.body;
  body.L = h.L;
  body.B = wind->Number("B").value_or(h.B);
  body.A_T = wind->Positive("A_T", "transverse projected area above water [m^2]");
  body.A_L = wind->Positive("A_L", "lateral projected area above water [m^2]");
  body.A_OD = wind->Positive("A_OD", "lateral area of the superstructure and deck cargo [m^2]");
  body.C = wind->Required("C", "centre of A_L ahead of midship [m]");
  body.C_BR = wind->Required("C_BR", "centre of A_OD ahead of midship [m]");
  body.H_BR = wind->Positive("H_BR", "height of the superstructure's top above water [m]");
  body.H_C = wind->Positive("H_C", "height of A_L's centre above water [m]");
  if (body.B <= 0) wind->FailKey("B", "must be above 0");
  if (body.A_OD > body.A_L)
    wind->FailKey("A_OD", "the superstructure's area " + FormatNumber(body.A_OD) +
                              " m^2 exceeds the whole lateral area A_L " + FormatNumber(body.A_L) +
                              " m^2");
  w.rho_air = wind->Number("rho_air").value_or(1.22);
  if (w.rho_air <= 0) wind->FailKey("rho_air", "must be above 0");
  const std::string model = wind->Text("model").value_or("fujiwara");
  if (model != "fujiwara" && model != "none")
    wind->FailKey("model",
                  "give fujiwara (the wind acts on the model) or none (the model "
                  "ignores it; the effect wind can still add it)");
  w.in_model = model == "fujiwara";
  wind->RefuseUnknown();
  return w;
}

// The coefficients the file gives, each one the estimates know (refused otherwise, naming them).
std::map<std::string, double> GivenCoefficients(YamlSection& top,
                                                const std::vector<MmgEstimate>& estimates,
                                                bool wind) {
  std::map<std::string, double> given;
  std::optional<YamlSection> coefficients = top.Child("coefficients");
  if (!coefficients) return given;
  for (const auto& [key, node] : coefficients->Items()) {
    const bool known = std::any_of(estimates.begin(), estimates.end(),
                                   [&](const MmgEstimate& e) { return e.name == key; });
    if (!known) {
      std::string names;
      for (const MmgEstimate& e : estimates) names += (names.empty() ? "" : ", ") + e.name;
      coefficients->Fail(node, key + ": unknown coefficient (known: " + names +
                                   "; m and I_zG are particulars, under hull" +
                                   (wind ? ")" : "; the wind's need a wind section)"));
    }
    given[key] = *coefficients->Number(key);
  }
  return given;
}

// The rudder's and the propeller's ranges as the simulators and maneuvers read them.
Actuation ActuationOf(const Controls& c) {
  Actuation a;
  const double full = c.rudder_max_deg * std::numbers::pi / 180.0;
  a.yaw_is_angle = true;
  a.yaw_full = full;
  a.yaw_full_deg = c.rudder_max_deg;
  a.thrust_cruise = c.n_cruise;
  // No wind unless measured; its direction either way round the compass.
  a.neutral = {0.0, c.n_cruise, 0.0, 0.0};
  a.input_min = {-full, c.n_min, 0.0, -2.0 * std::numbers::pi};
  a.input_max = {full, c.n_max, 100.0, 2.0 * std::numbers::pi};
  a.yaw_sign = c.sign == "ittc" ? -1.0 : 1.0;
  a.yaw_rate_limit = c.rudder_rate_deg_s * std::numbers::pi / 180.0;
  return a;
}

}  // namespace

VesselFile ReadVesselFile(const std::string& path) {
  const YAML::Node root = LoadYamlFile(path, "vessel file");
  YamlSection top(path, root, "");
  VesselFile out;
  out.name = top.Text("name").value_or(std::filesystem::path(path).stem().string());

  MmgHull h;
  h.rho = top.Number("rho").value_or(1025.0);
  if (h.rho <= 0) top.FailKey("rho", "must be above 0, got " + FormatNumber(h.rho));
  const YawInertia yaw = ReadHull(top, h);

  YamlSection prop = top.RequiredChild("propeller", "diameter and position");
  h.D_P = prop.Positive("D", "propeller diameter [m]");
  const double x_P = prop.Number("x").value_or(-0.48 * h.L);
  prop.RefuseUnknown();

  YamlSection rud = top.RequiredChild("rudder", "area, span and position");
  h.A_R = rud.Positive("area", "rudder area [m^2]");
  h.H_R = rud.Positive("span", "rudder span H_R [m]");
  const double x_R = rud.Number("x").value_or(-0.5 * h.L);
  rud.RefuseUnknown();

  const Controls controls = ReadControls(top);
  const WindPart wind = ReadWind(top, h);

  // Coefficients: what is given, else the estimate.
  std::vector<MmgEstimate> estimates = EstimateMmgCoefficients(h);
  if (wind.present)
    for (MmgEstimate& e : EstimateWindCoefficients(wind.body)) estimates.push_back(std::move(e));
  const std::map<std::string, double> given = GivenCoefficients(top, estimates, wind.present);
  top.RefuseUnknown();

  std::vector<double> p(Mmg::kDefaultParams.begin(), Mmg::kDefaultParams.end());
  auto set = [&](std::string_view name, double v) {
    const auto it = std::find(Mmg::kParamNames.begin(), Mmg::kParamNames.end(), name);
    p[it - Mmg::kParamNames.begin()] = v;
  };
  for (const MmgEstimate& e : estimates) {
    const auto g = given.find(e.name);
    if (g != given.end()) {
      set(e.name, g->second);
    } else {
      set(e.name, e.value);
      char value[32];
      std::snprintf(value, sizeof value, "%.4g", e.value);
      out.estimated.push_back(e.name + " = " + value + " (" + e.source + ")");
    }
  }
  set("m", h.mass);
  set("I_zG", yaw.I_zG ? *yaw.I_zG : h.mass * std::pow(*yaw.k_zz * h.L, 2));
  set("rho", h.rho);
  set("L", h.L);
  set("d", h.d);
  set("x_G", h.x_G);
  set("D_P", h.D_P);
  set("A_R", h.A_R);
  set("H_R", h.H_R);
  set("x_P", x_P / h.L);
  set("x_R", x_R / h.L);
  set("delta_sign", controls.sign == "ittc" ? -1.0 : 1.0);
  set("rho_air", wind.rho_air);
  set("A_T", wind.body.A_T);
  set("A_L", wind.body.A_L);
  set("wind_factor", wind.in_model ? 1.0 : 0.0);
  out.params = std::move(p);
  out.wind_body = wind.present;
  out.length_m = h.L;
  out.warnings = OutsideValidity(h);
  out.actuation = ActuationOf(controls);
  return out;
}

}  // namespace usvid
