// Free runs of consecutive windows side by side (the short-horizon fits) give each window what
// its own free run gives, bit for bit: the same start, inputs held with the model's delay inside
// the window, sub-steps of irregular intervals, per-window bounds, and a diverged window holding
// its last value while the others run on.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "core/dataset.h"
#include "core/error.h"
#include "metrics/free_run.h"

namespace usvid {
namespace {

class FreeRunWindowsTest : public ::testing::Test {
 protected:
  // A vessel-like record: u, v, r, psi, north, east and two inputs, at irregular stamps.
  static Dataset Record(Eigen::Index rows) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> jitter(0.03, 0.12);
    std::normal_distribution<double> noise(0.0, 1.0);
    Eigen::VectorXd t(rows);
    t(0) = 3.0;  // time need not start at 0
    for (Eigen::Index k = 1; k < rows; ++k) t(k) = t(k - 1) + jitter(rng);
    Dataset d(t);
    for (const char* c : {"u", "v", "r", "psi", "north", "east", "n", "delta"}) {
      Eigen::VectorXd x(rows);
      for (Eigen::Index k = 0; k < rows; ++k) x(k) = std::sin(0.05 * k + c[0]) + 0.1 * noise(rng);
      d.Set(c, x);
    }
    return d;
  }

  static void ExpectSameAsEachWindowAlone(const nlohmann::json& model, const Dataset& data,
                                          const std::vector<Eigen::Index>& starts) {
    const FreeRun together = FreeRunWindows(model, data, starts);
    bool any_diverged = false;
    for (size_t j = 0; j < starts.size(); ++j) {
      const Eigen::Index end = j + 1 < starts.size() ? starts[j + 1] : data.rows();
      const FreeRun alone = FreeRunModel(model, data.Rows(starts[j], end - starts[j]));
      any_diverged |= alone.diverged;
      ASSERT_EQ(together.channels, alone.channels);
      for (const std::string& c : alone.channels)
        for (Eigen::Index k = 0; k < end - starts[j]; ++k) {
          const double a = together.simulated[c](starts[j] + k), b = alone.simulated[c](k);
          ASSERT_TRUE(a == b || (std::isnan(a) && std::isnan(b)))
              << c << " window " << j << " row " << k << ": " << a << " against " << b;
        }
    }
    EXPECT_EQ(together.diverged, any_diverged);
  }
};

TEST_F(FreeRunWindowsTest, EachWindowIsItsOwnFreeRunBitForBit) {
  const nlohmann::json model = {{"equations",
                                 {{"u", "-0.3*u + 0.2*n - 0.05*abs(u)*u + v*r"},
                                  {"v", "-0.8*v - 0.4*u*r + 0.1*delta*u"},
                                  {"r", "-0.6*r + 0.3*u*delta - 0.02*v"}}},
                                {"preprocessing", {{"delay_s", 0.25}}}};
  const Dataset data = Record(400);
  ExpectSameAsEachWindowAlone(model, data, {0, 50, 120, 121, 300, 399});
  ExpectSameAsEachWindowAlone(model, data, {0});
}

TEST_F(FreeRunWindowsTest, ADivergedWindowHoldsItsLastValueAndTheOthersRunOn) {
  // r grows by e^(2 t): it leaves its bound within a few seconds of every window's start.
  const nlohmann::json model = {
      {"equations", {{"u", "-0.3*u + 0.2*n"}, {"v", "-v"}, {"r", "2*r + 0.01"}}}};
  const Dataset data = Record(300);
  ExpectSameAsEachWindowAlone(model, data, {0, 100, 180, 290});
  EXPECT_TRUE(FreeRunWindows(model, data, {0, 100, 180, 290}).diverged);
}

TEST_F(FreeRunWindowsTest, VessellessModelsWithoutKinematicsAndMissingChannels) {
  // A heading model (r alone, psi integrated) and a model that reads a channel the data lack.
  const Dataset data = Record(200);
  ExpectSameAsEachWindowAlone({{"equations", {{"r", "-0.5*r + 0.2*delta"}}}}, data, {0, 77});
  EXPECT_THROW(FreeRunWindows({{"equations", {{"r", "-r + rudder"}}}}, data, {0, 10}), InputError);
}

}  // namespace
}  // namespace usvid
