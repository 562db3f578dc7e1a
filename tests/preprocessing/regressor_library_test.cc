// The candidate library's rudder-inflow columns (preprocessing/regressor_library.h,
// docs/baselines.md#the-rudders-inflow): a rudder behind a propeller meets the water at a speed
// whose square is a quadratic form in u and the revolutions ahead, and its force grows with
// that square. The library holds that force exactly, and names each column in the equation
// syntax that model.json writes.
#include "preprocessing/regressor_library.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "core/dataset.h"
#include "core/expression.h"

namespace usvid {
namespace {

constexpr int kRows = 400;

// A record that goes ahead and astern on the propeller and on the hull, with a rudder that
// swings both ways, each channel drawn independently (fixed seed): u in [-0.15, 0.45] m/s,
// n in [-10, 16] 1/s, delta within +-0.6 rad.
struct Record {
  Eigen::VectorXd u, v, r, n, delta;
};

Record Swinging() {
  std::mt19937 rng(7);
  auto draw = [&](double lo, double hi) {
    std::uniform_real_distribution<double> d(lo, hi);
    Eigen::VectorXd x(kRows);
    for (double& e : x) e = d(rng);
    return x;
  };
  return {draw(-0.15, 0.45), draw(-0.02, 0.02), draw(-0.04, 0.04), draw(-10, 16), draw(-0.6, 0.6)};
}

LibraryOptions Plain() { return {.constant = true, .products = true, .abs_terms = true}; }

LibraryOptions WithRudder() {
  LibraryOptions o = Plain();
  o.rudder_inflow = true;
  return o;
}

// MMG's rudder inflow behind a propeller, reduced to what the library can hold: the hull's
// wake on u, and the propeller's wash added only while it turns ahead. The yaw moment is
// proportional to u_R^2 delta.
Eigen::VectorXd RudderMoment(const Record& rec) {
  Eigen::VectorXd m(kRows);
  for (int i = 0; i < kRows; ++i) {
    const double ahead = std::max(rec.n(i), 0.0);
    const double inflow_sq =
        0.6 * std::abs(rec.u(i)) * rec.u(i) + 0.004 * rec.u(i) * ahead + 2.5e-4 * ahead * ahead;
    m(i) = -0.08 * inflow_sq * rec.delta(i);
  }
  return m;
}

TEST(RegressorLibraryTest, HoldsTheForceOfARudderBehindAPropellerAheadAndAstern) {
  const Record rec = Swinging();
  const std::vector<NamedSignal> states = {{"u", rec.u}, {"v", rec.v}, {"r", rec.r}};
  const std::vector<NamedSignal> inputs = {{"n", rec.n}, {"delta", rec.delta}};
  const Eigen::VectorXd moment = RudderMoment(rec);

  const RegressorLibrary with = BuildLibrary(states, inputs, WithRudder());
  EXPECT_GT(FitLeastSquares(with.columns, moment).r2, 1.0 - 1e-12);
  // Without them, products of two channels (u delta, n delta, |n| n among the input products)
  // approach a third-order force but leave 7 % of its variance here.
  LibraryOptions products = Plain();
  products.input_products = true;
  EXPECT_LT(FitLeastSquares(BuildLibrary(states, inputs, products).columns, moment).r2, 0.99);
}

TEST(RegressorLibraryTest, TheRudderColumnsComeLastAndAreWrittenInTheEquationSyntax) {
  const Record rec = Swinging();
  const std::vector<NamedSignal> states = {{"u", rec.u}, {"v", rec.v}, {"r", rec.r}};
  const std::vector<NamedSignal> inputs = {{"n", rec.n}, {"delta", rec.delta}};
  const RegressorLibrary plain = BuildLibrary(states, inputs, Plain());
  const RegressorLibrary with = BuildLibrary(states, inputs, WithRudder());
  ASSERT_EQ(with.names.size(), plain.names.size() + 3);
  EXPECT_TRUE(std::equal(plain.names.begin(), plain.names.end(), with.names.begin()));
  EXPECT_EQ(with.names[plain.names.size()], "abs(u)*u*delta");

  Dataset data(Eigen::VectorXd::LinSpaced(kRows, 0.0, 0.05 * (kRows - 1)));
  for (const NamedSignal& s : states) data.Set(s.name, s.values);
  for (const NamedSignal& s : inputs) data.Set(s.name, s.values);
  for (size_t c = plain.names.size(); c < with.names.size(); ++c) {
    const Eigen::VectorXd parsed = Expression::Parse(with.names[c]).Evaluate(data);
    EXPECT_LT((parsed - with.columns.col(static_cast<Eigen::Index>(c))).cwiseAbs().maxCoeff(),
              1e-12)
        << with.names[c];
  }
  // Astern on the propeller the wash leaves the rudder: the two columns in n+ vanish.
  for (int i = 0; i < kRows; ++i)
    if (rec.n(i) < 0) {
      EXPECT_EQ(with.columns(i, static_cast<Eigen::Index>(plain.names.size()) + 1), 0.0);
      EXPECT_EQ(with.columns(i, static_cast<Eigen::Index>(plain.names.size()) + 2), 0.0);
    }
}

TEST(RegressorLibraryTest, TheRudderColumnsUseTheChannelsThereAre) {
  const Record rec = Swinging();
  // KVLCC2's propeller channel is rev [rev/min].
  const RegressorLibrary rev = BuildLibrary({{"u", rec.u}, {"r", rec.r}},
                                            {{"delta", rec.delta}, {"rev", rec.n}}, WithRudder());
  EXPECT_EQ(rev.names.back(), "(rev+abs(rev))*(rev+abs(rev))*delta");
  // Without a propeller channel, the hull's inflow alone.
  const RegressorLibrary hull =
      BuildLibrary({{"u", rec.u}, {"r", rec.r}}, {{"delta", rec.delta}}, WithRudder());
  EXPECT_EQ(hull.names.back(), "abs(u)*u*delta");
  EXPECT_EQ(
      hull.names.size(),
      BuildLibrary({{"u", rec.u}, {"r", rec.r}}, {{"delta", rec.delta}}, Plain()).names.size() + 1);
  // A waterjet's nozzle is not a rudder: its force is the jet's thrust.
  const RegressorLibrary jet = BuildLibrary(
      {{"u", rec.u}, {"r", rec.r}}, {{"throttle", rec.n}, {"nozzle", rec.delta}}, WithRudder());
  EXPECT_EQ(jet.names, BuildLibrary({{"u", rec.u}, {"r", rec.r}},
                                    {{"throttle", rec.n}, {"nozzle", rec.delta}}, Plain())
                           .names);
}

}  // namespace
}  // namespace usvid
