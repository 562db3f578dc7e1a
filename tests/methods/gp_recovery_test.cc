// GP-OLS recovers the true equations at its defaults (issues 5 and 18), checked on held-out data:
//  - msd, 1 % noise: v' = -0.2 x - 0.1 v + 0.1 f to 1 % relative RMS error in 9 of 10 seeds,
//    with the number of terms chosen by held-out error (no threshold set by hand);
//  - odin3dof with +,-,*,abs, random steps at 0.5 % noise, `identify` at its defaults: u', v',
//    r' of docs/vessels/odin3dof.md to 2 % relative RMS error on a held-out multisine run
//    (tools/gp-recovery-tables.sh measures the same over 10 seeds).
// The error is that of the identified right-hand side against the true one, both evaluated at
// the clean states and inputs of the held-out run.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "core/expression.h"
#include "methods/gp/gp_identify.h"
#include "methods/gp/search.h"
#include "methods/identify.h"
#include "metrics/evaluation.h"
#include "preprocessing/pipeline.h"
#include "simulators/msd.h"
#include "simulators/odin3dof.h"
#include "tests/support/synthetic_data.h"

namespace usvid {
namespace {

using testing::RelativeError;
using testing::Simulate;
using testing::TrueDerivative;

class GpRecoveryTest : public ::testing::Test {
 public:
  static gp::GpProblem Problem(const Dataset& d, const std::vector<std::string>& vars,
                               const Eigen::VectorXd& target) {
    gp::GpProblem p;
    p.names = vars;
    for (const std::string& v : vars) p.variables.push_back(d[v]);
    p.target = target;
    return p;
  }
};

TEST_F(GpRecoveryTest, MsdFromOnePercentNoiseInNineOfTenSeeds) {
  const std::vector<std::string> vars = {"x", "v", "f"};
  const Dataset held = Simulate("msd", "multisine", 300, 0.0, 999);
  const Eigen::VectorXd truth = TrueDerivative<Msd>(held, 1);
  int recovered = 0;
  for (uint64_t seed = 1; seed <= 10; ++seed) {
    const Dataset train = Simulate("msd", "random-steps", 300, 0.01, seed);
    const PreparedData prep = Preprocess(train, {"x", "v"}, {"f"}, {});
    gp::GpOptions opt;
    opt.population = 300;
    opt.generations = 20;
    opt.seed = seed;
    const gp::GpResult r = gp::RunGp(Problem(prep.data, vars, prep.data["v_dot"]), opt);
    const double err = RelativeError(gp::Predict(r.best, {held["x"], held["v"], held["f"]}), truth);
    recovered += err <= 0.01;
    std::cout << "seed " << seed << ": v' = " << r.best.Equation(vars) << "  held-out error " << err
              << " (" << r.seconds << " s)\n";
  }
  EXPECT_GE(recovered, 9);
}

struct Odin3DofRun {
  std::vector<double> errors;  // held-out relative errors of u', v', r'
  nlohmann::json equations;
};

// GP on odin3dof random steps with the given operators, scored on a held-out multisine run;
// computed once per operator set.
const Odin3DofRun& RunOdin3Dof(const std::vector<gp::Op>& functions) {
  static std::map<std::string, Odin3DofRun> cache;
  const std::string key = gp::Symbol(functions.back());
  if (cache.count(key)) return cache.at(key);
  const std::vector<std::string> vars = {"u", "v", "r", "tau_x", "tau_y", "tau_n"};
  const Dataset train = Simulate("odin3dof", "random-steps", 600, 0.005, 5);
  const Dataset held = Simulate("odin3dof", "multisine", 300, 0.0, 77);
  IdentifyRequest request;
  request.method = "gp";
  request.vessel = "odin3dof";
  request.options = {{"operators", gp::OperatorList(functions)}};
  request.seed = 3;
  const nlohmann::json model = Identify(train, request);
  Odin3DofRun run;
  int index = 3;
  for (const std::string state : {"u", "v", "r"}) {
    const std::string eq = model["equations"][state].get<std::string>();
    const double err = RelativeError(Expression::Parse(eq).Evaluate(held),
                                     TrueDerivative<Odin3Dof>(held, index++));
    const nlohmann::json& d = model["gp"]["equations"][state];
    std::cout << "[" << key << "] " << state << "' = " << eq << "\n  held-out error " << err << " ("
              << d["generations"] << " generations, " << d["stop_reason"] << ")\n";
    run.errors.push_back(err);
    run.equations[state] = eq;
  }
  return cache[key] = run;
}

const std::vector<gp::Op> kWithAbs = {gp::Op::kAdd, gp::Op::kSub, gp::Op::kMul, gp::Op::kAbs};
const std::vector<gp::Op> kReportSet = {gp::Op::kAdd, gp::Op::kSub, gp::Op::kMul};

// With abs, each of u', v', r' within 2 % on the held-out multisine run.
TEST_F(GpRecoveryTest, Odin3DofWithAbsFromRandomSteps) {
  for (double e : RunOdin3Dof(kWithAbs).errors) EXPECT_LE(e, 0.02);
}

// Issue 6's bar for gp: the model free-runs held-out multisine runs at 90 % or more (median
// over six runs, seeds 1 to 6: the hull is unstable, so one run's fit depends on the run).
TEST_F(GpRecoveryTest, Odin3DofWithAbsFreeRunsHeldOutMultisine) {
  const nlohmann::json model = {{"states", {"u", "v", "r"}},
                                {"inputs", {"tau_x", "tau_y", "tau_n"}},
                                {"equations", RunOdin3Dof(kWithAbs).equations}};
  std::map<std::string, std::vector<double>> fits;
  for (uint64_t seed = 1; seed <= 6; ++seed) {
    const Evaluation e = EvaluateModel(model, Simulate("odin3dof", "multisine", 300, 0.0, seed));
    for (const char* c : {"u", "v", "r"})
      fits[c].push_back(e.metrics.at(c).at("fit_percent").get<double>());
  }
  for (auto& [c, f] : fits) {
    std::sort(f.begin(), f.end());
    EXPECT_GE(0.5 * (f[2] + f[3]), 90.0) << c;
  }
}

// The report's set +,-,* cannot write |v| v or |r| r (sway and yaw change sign): its models
// are reported as they are, and they are worse than those with abs.
TEST_F(GpRecoveryTest, Odin3DofWithoutAbsIsWorse) {
  const std::vector<double>& with_abs = RunOdin3Dof(kWithAbs).errors;
  const std::vector<double>& without = RunOdin3Dof(kReportSet).errors;
  EXPECT_GT(without[1], with_abs[1]);
  EXPECT_GT(without[2], with_abs[2]);
}

}  // namespace
}  // namespace usvid
