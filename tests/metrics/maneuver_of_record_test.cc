// Which test a record holds (metrics/maneuver_of_record.h): simulated kvlcc2 zig-zags and turns
// either way give back the spec they were run with, a random-steps record is neither, and a
// record without a rudder is refused. On the shared Esso Osaka runs (a hand-steered start, a
// logged rudder a little off its order), every zig-zag and turning circle gives the spec the
// study replays it with (docs/studies/esso-osaka-mmg.json). Either kind is told from the record
// itself: MARIN's KVLCC2 zig-zags and turning circle, in one folder, give the specs the real
// suite's KVLCC2 track names by hand (harness/tracks/kvlcc2.yaml), and zz_20 its mirror.
#include "metrics/maneuver_of_record.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <numbers>
#include <random>
#include <string>

#include "core/error.h"
#include "importers/column_map.h"
#include "importers/csv_log.h"
#include "importers/hsva_dat.h"
#include "importers/marin_dat.h"
#include "maneuvers/maneuver_factory.h"
#include "metrics/closed_loop_replay.h"
#include "metrics/maneuver_header.h"
#include "metrics/zigzag_response.h"
#include "simulation/vessel_simulator.h"

namespace usvid {
namespace {

Dataset Simulated(const std::string& spec, double seconds) {
  const VesselSimulator& sim = FindVessel("kvlcc2");
  const VesselInfo& info = sim.Info();
  auto m = MakeManeuver(spec, info.actuation, seconds, 3);
  return sim.RunManeuver(*m, info.default_params, {}, RunOptions{}).data;
}

TEST(ManeuverOfRecordTest, ASimulatedTestGivesBackItsSpec) {
  // kvlcc2's rudder is ITTC-signed (positive to port); the spec's angle is starboard positive.
  EXPECT_EQ(ManeuverOfRecord(Simulated("zigzag:20/20", 900), "zigzag"), "zigzag:20/20");
  EXPECT_EQ(ManeuverOfRecord(Simulated("zigzag:-10/10", 900), "zigzag"), "zigzag:-10/10");
  EXPECT_EQ(ManeuverOfRecord(Simulated("turning:35", 900), "turning"), "turning:35");
  EXPECT_EQ(ManeuverOfRecord(Simulated("turning:-35", 900), "turning"), "turning:-35");
  EXPECT_EQ(ManeuverOfRecord(Simulated("zigzag:20/20", 900), "turning"), "");
  // Either kind, told apart by the side the rudder holds its angle to; random steps hold none.
  EXPECT_EQ(ManeuverOfRecord(Simulated("zigzag:-10/10", 900), "any"), "zigzag:-10/10");
  EXPECT_EQ(ManeuverOfRecord(Simulated("turning:-35", 900), "any"), "turning:-35");
  EXPECT_EQ(ManeuverOfRecord(Simulated("random-steps", 900), "any"), "");
  Dataset no_rudder = Simulated("zigzag:20/20", 100);
  no_rudder.Set("delta", Eigen::VectorXd::Zero(no_rudder.rows()));
  EXPECT_EQ(ManeuverOfRecord(no_rudder, "zigzag"), "");
  EXPECT_THROW(ManeuverOfRecord(no_rudder, "zigzag", "psi", "flap"), InputError);
  EXPECT_THROW(ManeuverOfRecord(no_rudder, "stopping"), InputError);
}

TEST(ManeuverOfRecordTest, TheHeadingCheckIsReadFromTheRecordNotTakenToBeTheRudderAngle) {
  // HSVA's KVLCC2 tests run B below A; the reversals are ordered at B, whatever A.
  for (const char* spec :
       {"zigzag:20/10", "zigzag:-35/5", "zigzag:10/1", "zigzag:-15/5", "zigzag:20/20"})
    EXPECT_EQ(ManeuverOfRecord(Simulated(spec, 900), "any"), spec);
  // A fast vessel turns up to 4.6 deg between two samples past B: still read as B.
  const VesselSimulator& hs = FindVessel("odin-hs");
  auto zz = MakeManeuver("zigzag:-20/10", hs.Info().actuation, 120, 1);
  const Dataset fast = hs.RunManeuver(*zz, hs.Info().default_params, {}, RunOptions{}).data;
  EXPECT_EQ(ManeuverOfRecord(fast, "zigzag", "psi", "nozzle"), "zigzag:-20/10");
}

TEST(ManeuverOfRecordTest, ARudderThatFlickersAboutZeroReversesNothing) {
  // A logged rudder that flickers about zero in its last digit (0.1 deg), at rest before the
  // execute and as it passes zero at each reversal, and a heading with 0.2 deg of noise: the same
  // test, execute and reversals as the clean record.
  const Dataset clean = Simulated("zigzag:-20/10", 600);
  Dataset d = clean;
  std::mt19937 rng(7);
  std::normal_distribution<double> flicker(0.0, 0.1 * std::numbers::pi / 180.0);
  Eigen::VectorXd delta = d["delta"], psi = d["psi"];
  for (double& x : delta)
    if (std::abs(x) < std::numbers::pi / 180.0) x += flicker(rng);
  for (double& x : psi) x += 2.0 * flicker(rng);
  d.Set("delta", delta);
  d.Set("psi", psi);
  const TestOfRecord read = ReadTestOfRecord(d, "any"), truth = ReadTestOfRecord(clean, "any");
  EXPECT_EQ(read.Spec(), "zigzag:-20/10");
  EXPECT_NEAR(read.execute_s, truth.execute_s, 0.5);
  const ZigzagResponse a = AnalyseZigzag(clean, 10, "psi", "delta", 20);
  const ZigzagResponse b = AnalyseZigzag(d, 10, "psi", "delta", 20);
  ASSERT_EQ(b.reversal_s.size(), a.reversal_s.size());
  for (size_t i = 0; i < a.reversal_s.size(); ++i)
    EXPECT_NEAR(b.reversal_s[i], a.reversal_s[i], 0.5) << i;
  EXPECT_EQ(b.first_turn, -1);
}

TEST(ManeuverOfRecordTest, TheLogsNameOfItsManeuverIsUsedAndCheckedAgainstTheRecord) {
  Dataset d = Simulated("zigzag:20/10", 900);
  d.metadata()["source"] = "HSVA_Z_20_10_S.dat";
  d.metadata()["maneuver"] = "Z20°/10° starting to starboard";
  TestOfRecord test = ReadTestOfRecord(d, "any");
  EXPECT_EQ(test.Spec(), "zigzag:20/10");
  EXPECT_EQ(test.named, "Z20°/10° starting to starboard");
  d.metadata()["maneuver"] = "Z20°/10°";  // no side named: the record's
  EXPECT_EQ(ManeuverOfRecord(d, "zigzag"), "zigzag:20/10");
  // Names the record contradicts, and one usvid does not know: refused, naming the file.
  for (const char* wrong : {"Z20°/10° starting to port", "Z20°/20°", "Z20°/1°", "Z15°/10°",
                            "T20° to starboard", "Williamson turn"}) {
    d.metadata()["maneuver"] = wrong;
    EXPECT_THAT([&] { ReadTestOfRecord(d, "any"); },
                testing::ThrowsMessage<InputError>(testing::HasSubstr("HSVA_Z_20_10_S.dat: ")))
        << wrong;
  }
}

// One of Esso Osaka's shared runs, its heading, rudder and track mapped.
Dataset EssoOsakaRun(const std::filesystem::path& file) {
  const std::vector<ColumnMapping> map = ParseColumnMap(
      {"t=t [s]", "north=x_position_mid [m]", "east=y_position_mid [m]", "psi=psi_hat [rad]",
       "r=r_angvelo [rad/s]", "n=n_prop [rps]", "delta=delta_rudder [rad]"});
  ImportReport report;
  return ImportCsvLog(file.string(), map, report);
}

TEST(ManeuverOfRecordTest, EachSharedEssoOsakaTestGivesTheStudysSpec) {
  const std::filesystem::path data = std::string(USVID_SHARED_DATA_DIR) + "/esso-osaka";
  if (!std::filesystem::exists(data)) GTEST_SKIP() << "shared data absent: " << data;
  const std::pair<const char*, const char*> runs[] = {
      {"zigzag/zigzag_31-Jul-2020_13_04_24.csv", "zigzag:20/20"},
      {"zigzag/zigzag_31-Jul-2020_13_14_21.csv", "zigzag:30/30"},
      {"zigzag/zigzag_31-Jul-2020_13_22_52.csv", "zigzag:15/15"},
      {"zigzag/zigzag_31-Jul-2020_13_29_19.csv", "zigzag:15/15"},
      {"zigzag/zigzag_31-Jul-2020_13_50_28.csv", "zigzag:-30/30"},
      {"zigzag/zigzag_31-Jul-2020_13_57_45.csv", "zigzag:20/20"},
      {"zigzag/zigzag_31-Jul-2020_14_03_39.csv", "zigzag:-20/20"},
      {"turning/turn_14-Sep-2020_13_39_32.csv", "turning:35"},
      {"turning/turn_14-Oct-2020_14_08_51.csv", "turning:35"},
      {"turning/turn_14-Sep-2020_14_16_04.csv", "turning:-35"},
      {"turning/turn_14-Sep-2020_15_47_33.csv", "turning:-35"},
      {"turning/turn_14-Oct-2020_15_21_57.csv", "turning:-35"}};
  for (const auto& [file, spec] : runs) {
    const Dataset d = EssoOsakaRun(data / file);
    EXPECT_EQ(ManeuverOfRecord(d, std::string(spec).substr(0, std::string(spec).find(':'))), spec)
        << file;
    EXPECT_EQ(ManeuverOfRecord(d, "any"), spec) << file;
  }
}

// Random steps put the rudder at a new angle at every step and hold none of them for most of
// the steering: no test, even asked for a zig-zag or a turn (it was read as zigzag:-15/1, its
// few reversals from its largest angle taken for a zig-zag's).
TEST(ManeuverOfRecordTest, RandomStepsHoldNoTest) {
  const Dataset d = Simulated("random-steps", 400);
  for (const char* kind : {"zigzag", "turning", "any"})
    EXPECT_EQ(ManeuverOfRecord(d, kind), "") << kind;
}

// A random run's rudder switches between +-35 deg, held to both sides as a 35/B zig-zag's is,
// but its reversals fall at scattered headings (half swings of 0.2 to 29 deg): no zig-zag is
// read from it, asked for one or for any test.
TEST(ManeuverOfRecordTest, ARandomRunsScatteredReversalsAreNoZigzag) {
  const std::filesystem::path data = std::string(USVID_SHARED_DATA_DIR) + "/esso-osaka";
  if (!std::filesystem::exists(data)) GTEST_SKIP() << "shared data absent: " << data;
  for (const char* file :
       {"random/random_03-Aug-2020_11_04_37.csv", "random/random_31-Jul-2020_12_29_58.csv",
        "random/random_31-Jul-2020_14_52_18.csv"}) {
    const Dataset d = EssoOsakaRun(data / file);
    const ZigzagCheckReading check = ReadZigzagCheck(d, "psi", "delta", 35);
    EXPECT_FALSE(check.Consistent())
        << file << ": " << check.agreeing << " of " << check.half_swings << " half swings agree";
    EXPECT_EQ(ManeuverOfRecord(d, "zigzag"), "") << file;
    EXPECT_THAT(ManeuverOfRecord(d, "any"), testing::Not(testing::StartsWith("zigzag"))) << file;
  }
}

TEST(ManeuverOfRecordTest, MarinsKvlcc2TestsAreToldApartFromTheirRecords) {
  const std::filesystem::path data = std::string(USVID_SHARED_DATA_DIR) + "/kvlcc2-marin";
  if (!std::filesystem::exists(data)) GTEST_SKIP() << "shared data absent: " << data;
  const std::pair<const char*, const char*> runs[] = {
      {"MARIN_FREE_KVLCC2_zz_20_m.dat", "zigzag:-20/20"},
      {"MARIN_FREE_KVLCC2_zz_-20_m.dat", "zigzag:20/20"},
      {"MARIN_FREE_KVLCC2_tc_35_m.dat", "turning:-35"}};
  for (const auto& [file, spec] : runs) {
    ImportReport report;
    EXPECT_EQ(ManeuverOfRecord(ImportMarinDat((data / file).string(), report), "any"), spec)
        << file;
  }
}

// HSVA's nine KVLCC2 zig-zags: the header's A and B (and side, where it names one) are what the
// record is read as, with the header and without it; and the first overshoot as the real suite
// reads it (metrics/closed_loop_replay.h's criteria) lies within 0.3 deg of a plain reading made
// here from the header's A and B: heading at the rudder's first movement, first and second zero
// crossings of the rudder, the furthest heading beyond B between them.
TEST(ManeuverOfRecordTest, HsvasZigzagsAreReadAsTheirHeadersSay) {
  const std::filesystem::path data = std::string(USVID_SHARED_DATA_DIR) + "/kvlcc2-hsva";
  if (!std::filesystem::exists(data)) GTEST_SKIP() << "shared data absent: " << data;
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(data)) {
    if (entry.path().extension() != ".dat") continue;
    ++files;
    const std::string file = entry.path().filename().string();
    ImportReport report;
    Dataset d = ImportHsvaDat(entry.path().string(), report);
    const NamedManeuver named = ParseManeuverHeader(d.metadata().at("maneuver"), file);
    const TestOfRecord test = ReadTestOfRecord(d, "any");
    EXPECT_EQ(test.rudder_deg, named.rudder_deg) << file;
    EXPECT_EQ(test.check_deg, named.check_deg) << file;
    if (named.side != 0) {
      EXPECT_EQ(test.first_turn, named.side) << file;
    }
    Dataset unnamed = d;
    unnamed.metadata().erase("maneuver");
    EXPECT_EQ(ManeuverOfRecord(unnamed, "any"), test.Spec()) << file << " without its header";
    // The plain reading.
    constexpr double kDeg = std::numbers::pi / 180.0;
    const Eigen::VectorXd& psi = d["psi"];
    const Eigen::VectorXd& delta = d["delta"];
    Eigen::Index k = 0;
    while (std::abs(delta(k) - delta(0)) <= kDeg) ++k;
    const double psi0 = psi(k);
    while (std::abs(delta(k)) < 0.5 * named.rudder_deg * kDeg) ++k;  // the first leg
    std::vector<Eigen::Index> crossings;
    for (Eigen::Index j = k + 1; j < d.rows() && crossings.size() < 2; ++j)
      if ((delta(j) > 0) != (delta(j - 1) > 0)) crossings.push_back(j);
    ASSERT_EQ(crossings.size(), 2u) << file;
    const double side = psi(crossings[0]) > psi0 ? 1.0 : -1.0;
    double furthest = -INFINITY;
    for (Eigen::Index j = crossings[0]; j < crossings[1]; ++j)
      furthest = std::max(furthest, side * (psi(j) - psi0));
    const double plain = furthest / kDeg - named.check_deg;
    const nlohmann::json criteria = ManeuverCriteria(test.Spec(), d, "psi", "delta");
    EXPECT_NEAR(criteria.at("first_overshoot_deg").get<double>(), plain, 0.3) << file;
  }
  EXPECT_EQ(files, 9);
}

}  // namespace
}  // namespace usvid
