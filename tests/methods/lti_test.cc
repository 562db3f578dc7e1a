// The linear time-invariant baseline (methods/lti/lti.h): on the mass-spring-damper, which is
// linear, it recovers the true coefficients (docs/model.md#msd: v' = -0.2 x - 0.1 v + 0.1 f);
// the ridge shrinks them; and a model without a constant writes none.
#include "methods/lti/lti.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "core/expression.h"
#include "preprocessing/pipeline.h"
#include "simulators/msd.h"
#include "tests/support/synthetic_data.h"

namespace usvid {
namespace {

using testing::RelativeError;
using testing::Simulate;
using testing::TrueDerivative;

const PreparedData& MsdRecord() {
  static const PreparedData prepared =
      Preprocess(Simulate("msd", "random-steps", 300, 0.01, 1), {"x", "v"}, {"f"}, {});
  return prepared;
}

TEST(LtiTest, RecoversTheMassSpringDamperOnHeldOutData) {
  const lti::LtiIdentification id = lti::IdentifyLti(MsdRecord(), {"v"}, {"x", "v"}, {"f"}, {});
  const nlohmann::json& p = id.parameters;
  // The truth (Msd's default parameters: m 10 kg, d 1 N s/m, k 2 N/m) to 2 % at 1 % noise.
  EXPECT_NEAR(p["v.x"].get<double>(), -0.2, 0.004);
  EXPECT_NEAR(p["v.v"].get<double>(), -0.1, 0.002);
  EXPECT_NEAR(p["v.f"].get<double>(), 0.1, 0.002);
  EXPECT_NEAR(p["v.1"].get<double>(), 0.0, 0.01);
  // The equation, as model.json carries it, against the true right-hand side on a held-out run.
  const Dataset held = Simulate("msd", "multisine", 300, 0.0, 999);
  const Eigen::VectorXd f = Expression::Parse(id.equations["v"].get<std::string>()).Evaluate(held);
  EXPECT_LE(RelativeError(f, TrueDerivative<Msd>(held, 1)), 0.01);
  EXPECT_GT(id.details["v"]["r2_train"].get<double>(), 0.99);
}

TEST(LtiTest, TheRidgeShrinksAndTheConstantCanBeLeftOut) {
  lti::LtiOptions options;
  options.constant = false;
  const lti::LtiIdentification plain =
      lti::IdentifyLti(MsdRecord(), {"v"}, {"x", "v"}, {"f"}, options);
  EXPECT_FALSE(plain.parameters.contains("v.1"));
  options.ridge = 1.0;  // as much penalty as each column's energy
  const lti::LtiIdentification ridged =
      lti::IdentifyLti(MsdRecord(), {"v"}, {"x", "v"}, {"f"}, options);
  for (const char* term : {"v.x", "v.v", "v.f"})
    EXPECT_LT(std::abs(ridged.parameters[term].get<double>()),
              std::abs(plain.parameters[term].get<double>()))
        << term;
  options.ridge = -1.0;
  EXPECT_THROW(lti::IdentifyLti(MsdRecord(), {"v"}, {"x", "v"}, {"f"}, options), InputError);
}

}  // namespace
}  // namespace usvid
