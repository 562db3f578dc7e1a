// Multi-rate channels are stored sparse (core/dataset.h, docs/data.md#multi-rate-channels): a
// channel sampled on at most a quarter of the rows costs its samples, not the rows, and reads
// the same through every accessor as it would dense.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <thread>

#include "core/csv_dataset.h"
#include "core/dataset.h"

namespace usvid {
namespace {

constexpr double kDenseBytesPerRow = sizeof(double) + sizeof(bool);

// t at `hz` for `seconds`; "gps" sampled every `every`-th row from row `offset`, "imu" on all.
Dataset MultiRateLog(double hz, double seconds, Eigen::Index every, Eigen::Index offset = 0) {
  const auto n = static_cast<Eigen::Index>(std::lround(hz * seconds)) + 1;
  Dataset d(Eigen::VectorXd::LinSpaced(n, 0.0, seconds));
  Eigen::VectorXd gps(n);
  Channel::Mask sampled(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    gps(k) = std::sin(0.01 * static_cast<double>(k));
    sampled(k) = k % every == offset;
  }
  d.Set("gps", gps, sampled);
  d.Set("imu", Eigen::VectorXd::LinSpaced(n, -1.0, 1.0));
  return d;
}

// Every accessor of `c` against the dense truth (`values`, NaN where !`sampled`).
void ExpectReads(const Channel& c, const Eigen::VectorXd& values, const Channel::Mask& sampled) {
  ASSERT_EQ(c.size(), values.size());
  EXPECT_EQ(c.SampleCount(), sampled.count());
  Eigen::Index visited = 0, last = -1;
  c.ForEachSample([&](Eigen::Index k, double v) {
    EXPECT_GT(k, last) << "ascending rows";
    EXPECT_TRUE(sampled(k));
    EXPECT_EQ(v, values(k));
    last = k;
    ++visited;
  });
  EXPECT_EQ(visited, sampled.count());
  for (Eigen::Index k = 0; k < values.size(); ++k) {
    ASSERT_EQ(c.IsSampled(k), sampled(k)) << "row " << k;
    if (sampled(k)) {
      ASSERT_EQ(c.Value(k), values(k));
      ASSERT_EQ(c.values()(k), values(k));
    } else {
      ASSERT_TRUE(std::isnan(c.Value(k)));
      ASSERT_TRUE(std::isnan(c.values()(k)));
    }
  }
  EXPECT_TRUE((c.sampled() == sampled).all());
}

// Issue 40's acceptance: a 100 Hz, 2-hour log with GPS at 1 Hz holds the GPS channel in at most
// 2 % of its dense memory (a double and a flag per row).
TEST(ChannelStorageTest, AOneHertzChannelOfATwoHourHundredHertzLogHoldsItsSamplesOnly) {
  const Dataset d = MultiRateLog(100.0, 7200.0, 100);
  const Channel& gps = d.Get("gps");
  ASSERT_EQ(d.rows(), 720001);
  EXPECT_TRUE(gps.Sparse());
  EXPECT_EQ(gps.SampleCount(), 7201);
  const double dense = kDenseBytesPerRow * static_cast<double>(d.rows());
  EXPECT_LE(static_cast<double>(gps.StorageBytes()), 0.02 * dense)
      << gps.StorageBytes() << " bytes against " << dense << " dense";
  EXPECT_FALSE(d.Get("imu").Sparse());
  EXPECT_EQ(static_cast<double>(d.Get("imu").StorageBytes()), dense);
}

TEST(ChannelStorageTest, SparseAndDenseStorageReadAlike) {
  for (const Eigen::Index every : {1, 2, 3, 4, 5, 10}) {
    SCOPED_TRACE("sampled every " + std::to_string(every) + " rows");
    const Dataset d = MultiRateLog(10.0, 99.9, every, every - 1);
    const Channel& gps = d.Get("gps");
    EXPECT_EQ(gps.Sparse(), every >= 4) << "sparse at a quarter of the rows or fewer";
    Eigen::VectorXd values(d.rows());
    Channel::Mask sampled(d.rows());
    for (Eigen::Index k = 0; k < d.rows(); ++k) {
      sampled(k) = k % every == every - 1;
      values(k) = sampled(k) ? std::sin(0.01 * static_cast<double>(k)) : NAN;
    }
    ExpectReads(gps, values, sampled);
  }
}

TEST(ChannelStorageTest, AWindowAndAKeptSubsetOfRowsStaySparseAndReadTheirRows) {
  const Dataset d = MultiRateLog(10.0, 200.0, 10, 3);
  const Channel& gps = d.Get("gps");
  ASSERT_TRUE(gps.Sparse());

  const Dataset window = d.Rows(25, 100);
  EXPECT_TRUE(window.Get("gps").Sparse());
  ExpectReads(window.Get("gps"), gps.values().segment(25, 100), gps.sampled().segment(25, 100));

  Dataset kept = d;
  std::vector<bool> keep(static_cast<size_t>(d.rows()));
  std::vector<Eigen::Index> rows;
  for (Eigen::Index k = 0; k < d.rows(); ++k)
    if ((keep[static_cast<size_t>(k)] = k % 3 != 0)) rows.push_back(k);
  kept.KeepRows(keep);
  const auto n = static_cast<Eigen::Index>(rows.size());
  Eigen::VectorXd values(n);
  Channel::Mask sampled(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    values(i) = gps.Value(rows[static_cast<size_t>(i)]);
    sampled(i) = gps.IsSampled(rows[static_cast<size_t>(i)]);
  }
  EXPECT_TRUE(kept.Get("gps").Sparse());
  ExpectReads(kept.Get("gps"), values, sampled);
  ExpectReads(d.Get("gps"), gps.values(), gps.sampled());  // the original is untouched
}

TEST(ChannelStorageTest, TheDenseFormOfASparseChannelIsBuiltOnceForConcurrentReaders) {
  const Dataset d = MultiRateLog(100.0, 600.0, 100);
  const Channel& gps = d.Get("gps");
  const std::size_t before = gps.StorageBytes();
  const double* seen[2] = {nullptr, nullptr};
  std::thread a([&] { seen[0] = gps.values().data(); });
  std::thread b([&] { seen[1] = gps.values().data(); });
  a.join();
  b.join();
  EXPECT_EQ(seen[0], seen[1]);
  EXPECT_EQ(gps.StorageBytes(), before + static_cast<std::size_t>(kDenseBytesPerRow * d.rows()))
      << "the dense form is held beside the samples once built";
  EXPECT_TRUE(gps.Sparse());
}

// Sampled rows out of order, repeated or outside the channel are a programming error, caught.
TEST(ChannelStorageDeathTest, FromSamplesRefusesRowsOutOfOrderOrOutside) {
  EXPECT_EQ(Channel::FromSamples("a", 10, {1, 5}, Eigen::Vector2d(1.0, 2.0)).SampleCount(), 2);
  EXPECT_DEATH(Channel::FromSamples("a", 10, {5, 1}, Eigen::Vector2d(1.0, 2.0)), "ascending");
  EXPECT_DEATH(Channel::FromSamples("a", 10, {5, 5}, Eigen::Vector2d(1.0, 2.0)), "ascending");
  EXPECT_DEATH(Channel::FromSamples("a", 10, {1, 10}, Eigen::Vector2d(1.0, 2.0)), "within");
  EXPECT_DEATH(Channel::FromSamples("a", 10, {1}, Eigen::Vector2d(1.0, 2.0)), "a value per");
}

// The CSV reader stores a sparsely filled column sparse, and writes it back cell for cell.
TEST(ChannelStorageTest, ACsvColumnWithFewFilledCellsReadsSparseAndWritesBackTheSameText) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "usvid_channel_storage_test";
  std::filesystem::create_directories(dir);
  const std::string in = (dir / "in.csv").string(), out = (dir / "out.csv").string();
  {
    std::ofstream f(in);
    f << "t,r,north\n";
    for (int k = 0; k < 200; ++k) {
      f << 0.01 * k << "," << 0.001 * k << ",";
      if (k % 10 == 0) f << 3.5 * k;
      f << "\n";
    }
  }
  const Dataset d = ReadDatasetCsv(in);
  EXPECT_TRUE(d.Get("north").Sparse());
  EXPECT_EQ(d.Get("north").SampleCount(), 20);
  EXPECT_FALSE(d.Get("r").Sparse());
  WriteDatasetCsv(out, d);
  const Dataset back = ReadDatasetCsv(out);
  ExpectReads(back.Get("north"), d.Get("north").values(), d.Get("north").sampled());
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace usvid
