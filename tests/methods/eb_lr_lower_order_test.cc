// eb-lr on records that are not a full step grid (methods/eb_lr/eb_lr.h, issue 70): with too few
// steady windows the polynomial's order is lowered and said in the warnings, an equation no
// window excites takes its first term from the transients, a record without any steady state is
// refused in one line, a held thrust is fitted only when asked, records joined with a gap are
// fitted without windowing or integrating across the join, and the method resamples a record
// whose time stamps are not uniform.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

#include "core/error.h"
#include "core/records.h"
#include "core/stretches.h"
#include "maneuvers/maneuver_factory.h"
#include "methods/eb_lr/eb_lr.h"
#include "methods/identify.h"
#include "sensors/noise.h"
#include "simulation/vessel_simulator.h"
#include "simulators/eb2dof.h"

namespace usvid {
namespace {

using eb_lr::EbLrIdentification;
using eb_lr::EbLrOptions;
using eb_lr::IdentifyWithEbLr;
using ::testing::HasSubstr;

class EbLrLowerOrderTest : public ::testing::Test {
 public:
  static Dataset Run(const std::string& maneuver, double seconds = 0.0, double noise = 0.001) {
    const VesselSimulator& sim = FindVessel("eb2dof");
    auto m = MakeManeuver(maneuver, sim.Info().actuation, seconds, 1);
    Dataset d = sim.RunManeuver(*m, sim.Info().default_params, {}, RunOptions{}).data;
    AddGaussianNoise(d, {"U", "r"}, noise, 3);
    return d;
  }
  static EbLrOptions Lowering() {
    EbLrOptions o;
    o.lower_order = true;
    return o;
  }
  static EbLrIdentification Identify(const Dataset& d, const EbLrOptions& o) {
    return IdentifyWithEbLr(d, "U", "r", "throttle", "nozzle", o);
  }
  static std::string Message(const std::function<void()>& f) {
    try {
      f();
    } catch (const InputError& e) {
      return e.what();
    }
    return "(no InputError)";
  }
  static double Truth(const char* name) {
    for (int i = 0; i < Eb2Dof::kParams; ++i)
      if (std::string(Eb2Dof::kParamNames[i]) == name) return Eb2Dof::kDefaultParams[i];
    return NAN;
  }
};

// Three windows of a step grid (two input steps): refused without lower_order, as before; with
// it, sigma_U keeps its first three terms and sigma_r what its windows excite, the warnings say
// which terms were dropped, and every coefficient is finite.
TEST_F(EbLrLowerOrderTest, FewWindowsLowerThePolynomialsOrder) {
  Dataset few = Run("stepgrid:5/3");
  std::vector<bool> keep(few.rows());
  for (Eigen::Index k = 0; k < few.rows(); ++k) keep[k] = few.t()(k) >= 290.0 && few.t()(k) < 335.0;
  few.KeepRows(keep);
  EXPECT_THAT(Message([&] { Identify(few, {}); }), HasSubstr("steady windows"));
  const EbLrIdentification id = Identify(few, Lowering());
  const auto& warnings = id.details.at("warnings");
  ASSERT_FALSE(warnings.empty());
  EXPECT_THAT(warnings[0].get<std::string>(), HasSubstr("sigma_U lowered to"));
  EXPECT_FALSE(id.parameters.contains("sigma_U.r*r"));
  EXPECT_TRUE(id.parameters.contains("sigma_U.U"));
  for (const auto& [name, value] : id.parameters.items())
    EXPECT_TRUE(std::isfinite(value.get<double>())) << name;
}

// A full step grid keeps every term with lower_order, and gives the same coefficients as without.
TEST_F(EbLrLowerOrderTest, AFullGridKeepsEveryTerm) {
  const Dataset grid = Run("stepgrid:3/2");
  const EbLrIdentification strict = Identify(grid, {});
  const EbLrIdentification lowered = Identify(grid, Lowering());
  EXPECT_TRUE(lowered.details.at("warnings").empty()) << lowered.details.at("warnings");
  EXPECT_EQ(strict.parameters, lowered.parameters);
}

// A zig-zag holds its throttle: refused unless constant_thrust, naming the input. Fitted, its one
// steady window (the approach) gives sigma_U on U alone, and since no steady turn excites
// sigma_r, its linear term r comes from the transients with the mass. At one speed that term
// stands for eb2dof's whole damping there, sr1 + srU U + sr3 r^2, and the mass for mr0 + mr1 U:
// both within 15 % at the zig-zag's mean speed and mean square rate.
TEST_F(EbLrLowerOrderTest, HeldThrustIsFittedWhenAskedOnTheSpeedsItReaches) {
  const Dataset zigzag = Run("zigzag:20/20", 300.0);
  EXPECT_THAT(Message([&] { Identify(zigzag, Lowering()); }), HasSubstr("'throttle' is constant"));
  EbLrOptions o = Lowering();
  o.constant_thrust = true;
  const EbLrIdentification id = Identify(zigzag, o);
  EXPECT_EQ(id.details.at("fit").at("sigma_r").at("from"), "transients");
  EXPECT_EQ(id.details.at("fit").at("sigma_U").at("basis"), "U");
  const double speed = zigzag["U"].mean(), rate2 = zigzag["r"].squaredNorm() / zigzag.rows();
  const double damping = Truth("sr1") + Truth("srU") * speed + Truth("sr3") * rate2;
  EXPECT_NEAR(id.parameters.at("sigma_r.r").get<double>(), damping, 0.15 * damping);
  const double mass = Truth("mr0") + Truth("mr1") * speed;
  const double fitted_mass =
      id.parameters.at("m_r.1").get<double>() + id.parameters.at("m_r.U").get<double>() * speed;
  EXPECT_NEAR(fitted_mass, mass, 0.15 * mass);
}

// A multisine never holds its inputs: no steady window, no steady state, one line.
TEST_F(EbLrLowerOrderTest, NoSteadyStateIsRefusedInOneLine) {
  const std::string why = Message([&] { Identify(Run("multisine", 300.0), Lowering()); });
  EXPECT_THAT(why, HasSubstr("found 0 steady windows: the record has no steady state"));
  EXPECT_EQ(why.find('\n'), std::string::npos);
}

// Two halves of a step grid joined, the second 1000 s after the first ends (core/records.h): fitted
// as stretches, nothing crosses the join, every coefficient within 5 % (at 0.1 % noise).
TEST_F(EbLrLowerOrderTest, JoinedRecordsAreFittedAsStretches) {
  const Dataset grid = Run("stepgrid:5/3");
  const double mid = grid.t()(grid.rows() / 2);
  Dataset first = grid, second = grid;
  std::vector<bool> a(grid.rows()), b(grid.rows());
  for (Eigen::Index k = 0; k < grid.rows(); ++k) a[k] = !(b[k] = grid.t()(k) >= mid);
  first.KeepRows(a);
  second.KeepRows(b);
  const Dataset joined = JoinRecords({first, second});
  const std::vector<Stretch> stretches = Stretches(joined.t(), kGridGapFactor);
  ASSERT_EQ(stretches.size(), 2u);
  EXPECT_THAT(Message([&] { Identify(joined, {}); }), HasSubstr("not uniform"));
  const EbLrIdentification id =
      IdentifyWithEbLr(joined, stretches, "U", "r", "throttle", "nozzle", Lowering());
  EXPECT_EQ(id.details.at("records"), 2);
  for (const char* p : {"mU0", "mr0", "sU1", "sU2", "sUr", "sr1", "srU", "sr3"}) {
    const std::string name = std::string(p) == "mU0"   ? "m_U.1"
                             : std::string(p) == "mr0" ? "m_r.1"
                             : std::string(p) == "sU1" ? "sigma_U.U"
                             : std::string(p) == "sU2" ? "sigma_U.U*U"
                             : std::string(p) == "sUr" ? "sigma_U.r*r"
                             : std::string(p) == "sr1" ? "sigma_r.r"
                             : std::string(p) == "srU" ? "sigma_r.U*r"
                                                       : "sigma_r.r*r*r";
    EXPECT_NEAR(id.parameters.at(name).get<double>(), Truth(p), 0.05 * std::abs(Truth(p))) << name;
  }
}

// The method resamples a record whose time stamps jitter, as every method does: usvid identify
// fits it instead of asking for a resampled record.
TEST_F(EbLrLowerOrderTest, TheMethodResamplesAJitteredRecord) {
  Dataset grid = Run("stepgrid:3/2");
  Eigen::VectorXd t = grid.t();
  for (Eigen::Index k = 1; k + 1 < t.size(); k += 2) t(k) += 0.2 * (t(k + 1) - t(k));
  grid.SetTime(t);
  IdentifyRequest r;
  r.method = "eb-lr";
  r.vessel = "eb2dof";
  const nlohmann::json model = usvid::Identify(grid, r);
  EXPECT_TRUE(model.at("eb_lr").at("warnings").empty()) << model.at("eb_lr").at("warnings");
  EXPECT_EQ(model.at("eb_lr").at("steady_windows").size(), 15u);
  for (const auto& [name, truth] :
       {std::pair{"sigma_r.r", "sr1"}, {"sigma_U.r*r", "sUr"}, {"m_r.1", "mr0"}, {"m_U.1", "mU0"}})
    EXPECT_NEAR(model.at("parameters").at(name).get<double>(), Truth(truth), 0.1 * Truth(truth))
        << name;
}

}  // namespace
}  // namespace usvid
