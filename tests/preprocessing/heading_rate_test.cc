// Rate of turn from a GPS-only heading: a heading wrapped into (-pi, pi] that crosses the wrap
// many times is unwrapped before differentiation, so the rate follows the true derivative with
// no spikes at the wraps; a heading that is missing or has unsampled cells is refused.
#include "preprocessing/heading_rate.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "core/dataset.h"
#include "core/error.h"

namespace usvid {
namespace {

constexpr double kPi = std::numbers::pi;

// Into (-pi, pi].
double Wrap(double a) { return a - 2 * kPi * std::ceil((a - kPi) / (2 * kPi)); }

struct HeadingRecord {
  Dataset data;
  Eigen::VectorXd true_rate;
};

// psi(t) = 3 sin(0.05 t) + 0.02 t plus Gaussian noise (sd 0.002 rad, fixed seed), wrapped into
// (-pi, pi], sampled at 2 Hz for 400 s; the true rate is 0.15 cos(0.05 t) + 0.02.
HeadingRecord WrappedHeading() {
  constexpr double kDt = 0.5;
  constexpr int kN = 801;
  std::mt19937_64 rng(20240611);
  std::normal_distribution<double> noise(0.0, 0.002);
  Eigen::VectorXd t(kN), psi(kN), rate(kN);
  for (int i = 0; i < kN; ++i) {
    t(i) = i * kDt;
    psi(i) = Wrap(3 * std::sin(0.05 * t(i)) + 0.02 * t(i) + noise(rng));
    rate(i) = 0.15 * std::cos(0.05 * t(i)) + 0.02;
  }
  HeadingRecord r{Dataset(t), rate};
  r.data.Set("psi", psi);
  return r;
}

TEST(HeadingRateTest, WrappedNoisyHeadingGivesTrueRate) {
  const HeadingRecord rec = WrappedHeading();
  const Eigen::VectorXd& psi = rec.data["psi"];
  // The record really wraps, many times: otherwise the test would not test the unwrapping.
  int wraps = 0;
  for (Eigen::Index k = 1; k < psi.size(); ++k) {
    ASSERT_GT(psi(k), -kPi);
    ASSERT_LE(psi(k), kPi);
    if (std::abs(psi(k) - psi(k - 1)) > kPi) ++wraps;
  }
  ASSERT_GE(wraps, 6);

  const Eigen::VectorXd rate = RateFromHeading(rec.data, "psi");
  ASSERT_EQ(rate.size(), psi.size());
  // RMS error over the middle 90 % (the natural spline's ends are biased), and no sample far off
  // (an unwrapping miss would leave a spike of about 2 pi / dt there).
  const Eigen::Index n = psi.size(), from = n / 20, to = n - n / 20;
  double sum_sq = 0.0, worst = 0.0;
  for (Eigen::Index k = from; k < to; ++k) {
    const double e = rate(k) - rec.true_rate(k);
    sum_sq += e * e;
    worst = std::max(worst, std::abs(e));
  }
  const double rms = std::sqrt(sum_sq / static_cast<double>(to - from));
  EXPECT_LT(rms, 0.003) << "worst " << worst;
  EXPECT_LT(worst, 0.01);
}

TEST(HeadingRateTest, MissingHeadingIsRefused) {
  HeadingRecord rec = WrappedHeading();
  rec.data.metadata()["source"] = "gps_log.csv";
  try {
    RateFromHeading(rec.data, "heading");
    FAIL() << "no InputError for a missing heading";
  } catch (const InputError& e) {
    // The message names the file and the missing column.
    EXPECT_NE(std::string(e.what()).find("gps_log.csv"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("heading"), std::string::npos) << e.what();
  }
}

TEST(HeadingRateTest, HeadingWithEmptyCellIsRefused) {
  HeadingRecord rec = WrappedHeading();
  Eigen::VectorXd psi = rec.data["psi"];
  Eigen::Array<bool, Eigen::Dynamic, 1> sampled =
      Eigen::Array<bool, Eigen::Dynamic, 1>::Constant(psi.size(), true);
  sampled(300) = false;
  rec.data.Set("psi", psi, sampled);
  EXPECT_THROW(RateFromHeading(rec.data, "psi"), InputError);
  // The same heading fully sampled is accepted.
  sampled(300) = true;
  rec.data.Set("psi", psi, sampled);
  EXPECT_NO_THROW(RateFromHeading(rec.data, "psi"));
}

}  // namespace
}  // namespace usvid
