// Which test a record holds (metrics/maneuver_of_record.h): simulated kvlcc2 zig-zags and turns
// either way give back the spec they were run with, a random-steps record is neither, and a
// record without a rudder is refused. On the shared Esso Osaka runs (a hand-steered start, a
// logged rudder a little off its order), every zig-zag and turning circle gives the spec the
// study replays it with (docs/studies/esso-osaka-mmg.json). Either kind is told from the record
// itself: MARIN's KVLCC2 zig-zags and turning circle, in one folder, give the specs the real
// suite's KVLCC2 track names by hand (harness/suites/real-kvlcc2.json), and zz_20 its mirror.
#include "metrics/maneuver_of_record.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "core/error.h"
#include "importers/column_map.h"
#include "importers/csv_log.h"
#include "importers/marin_dat.h"
#include "maneuvers/maneuver_factory.h"
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

TEST(ManeuverOfRecordTest, EachSharedEssoOsakaTestGivesTheStudysSpec) {
  const std::filesystem::path data = std::string(USVID_SHARED_DATA_DIR) + "/esso-osaka";
  if (!std::filesystem::exists(data)) GTEST_SKIP() << "shared data absent: " << data;
  const std::vector<ColumnMapping> map = ParseColumnMap(
      {"t=t [s]", "north=x_position_mid [m]", "east=y_position_mid [m]", "psi=psi_hat [rad]",
       "r=r_angvelo [rad/s]", "n=n_prop [rps]", "delta=delta_rudder [rad]"});
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
    ImportReport report;
    const Dataset d = ImportCsvLog((data / file).string(), map, report);
    EXPECT_EQ(ManeuverOfRecord(d, std::string(spec).substr(0, std::string(spec).find(':'))), spec)
        << file;
    EXPECT_EQ(ManeuverOfRecord(d, "any"), spec) << file;
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

}  // namespace
}  // namespace usvid
