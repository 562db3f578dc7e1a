// The real suite's tracks (harness/real_suite.h) on a data folder: the shared runs, and every
// further run of a track's folders added as a held-out test (the papers' test runs, where a
// folder holds them; another tank's KVLCC2 tests, as MARIN's .dat or usvid's own CSV), re-run
// closed-loop as its record says when it is a zig-zag or a turn. Skips without ../shared/data.
#include "harness/real_suite.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "core/csv_dataset.h"
#include "importers/marin_dat.h"

namespace usvid {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

const fs::path kShared = USVID_SHARED_DATA_DIR;

fs::path TempDir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("usvid_real_suite_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::vector<std::string> TestNames(const Suite& s) {
  std::vector<std::string> names;
  for (const SuiteData& d : s.test_data) names.push_back(d.name);
  return names;
}

TEST(RealSuiteTest, FurtherRunsOfTheFolderAreScoredAsHeldOutTests) {
  if (!fs::exists(kShared / "esso-osaka") || !fs::exists(kShared / "kvlcc2-marin"))
    GTEST_SKIP() << "shared data absent: " << kShared;
  const fs::path dir = TempDir("further");
  const fs::path data = dir / "data";
  fs::create_directories(data);
  // A copy of the KVLCC2 folder with two runs more, a zig-zag and a turning circle, named as
  // another tank might name them.
  fs::create_directories(data / "kvlcc2-marin");
  for (const auto& e : fs::directory_iterator(kShared / "kvlcc2-marin"))
    fs::create_symlink(fs::absolute(e.path()), data / "kvlcc2-marin" / e.path().filename());
  fs::create_symlink(fs::absolute(kShared / "kvlcc2-marin/MARIN_FREE_KVLCC2_zz_-20_m.dat"),
                     data / "kvlcc2-marin/other_tank_a.dat");
  fs::create_symlink(fs::absolute(kShared / "kvlcc2-marin/MARIN_FREE_KVLCC2_tc_35_m.dat"),
                     data / "kvlcc2-marin/other_tank_b.dat");
  // And one in usvid's own data format, as usvid import writes another tank's log.
  ImportReport report;
  WriteDatasetCsv(
      (data / "kvlcc2-marin/other_tank_c.csv").string(),
      ImportMarinDat((kShared / "kvlcc2-marin/MARIN_FREE_KVLCC2_zz_-20_m.dat").string(), report));
  // A copy of the Esso folder with one run more: a zig-zag the shared folder does not have.
  for (const char* sub : {"zigzag", "turning", "random", "berthing"}) {
    fs::create_directories(data / "esso-osaka" / sub);
    for (const auto& e : fs::directory_iterator(kShared / "esso-osaka" / sub))
      fs::create_symlink(fs::absolute(e.path()), data / "esso-osaka" / sub / e.path().filename());
  }
  fs::create_symlink(fs::absolute(kShared / "esso-osaka/zigzag/zigzag_31-Jul-2020_13_04_24.csv"),
                     data / "esso-osaka/zigzag/zigzag_from_the_paper.csv");

  const std::vector<SuiteTrack> tracks = RealSuiteTracks(data.string(), (dir / "out").string());
  ASSERT_EQ(tracks.size(), 2u);
  const SuiteTrack& kvlcc2 = tracks[0];
  const SuiteTrack& esso = tracks[1];
  EXPECT_EQ(kvlcc2.name, "kvlcc2");
  EXPECT_THAT(TestNames(kvlcc2.suite),
              ::testing::ElementsAre("zigzag -20/20", "turning 35", "other_tank_a", "other_tank_b",
                                     "other_tank_c"));
  // The folder holds both kinds of test: each further run's is read from its record, and is
  // the spec the track gives the same record by hand.
  const std::vector<SuiteData>& tests = kvlcc2.suite.test_data;
  ASSERT_EQ(tests.size(), 5u);
  EXPECT_EQ(tests[2].maneuver, tests[0].maneuver);
  EXPECT_EQ(tests[3].maneuver, tests[1].maneuver);
  EXPECT_EQ(tests[4].maneuver, tests[0].maneuver);
  EXPECT_EQ(tests[2].format, "marin-dat");
  EXPECT_EQ(tests[4].format, "csv");
  ASSERT_EQ(kvlcc2.notes.size(), 2u);
  EXPECT_THAT(kvlcc2.notes[0], HasSubstr("3 further runs of the data folder"));
  // The folder has no HSVA tank: its own track and the cross-facility ones are skipped.
  EXPECT_THAT(kvlcc2.notes[1], HasSubstr("tracks kvlcc2-hsva, kvlcc2-hsva-to-marin, "
                                         "kvlcc2-marin-to-hsva skipped"));

  EXPECT_EQ(esso.name, "esso-osaka");
  const std::vector<std::string> names = TestNames(esso.suite);
  // Every zig-zag, turning and random run but the eight it trains on (the folder's further runs
  // too, the added one among them); no berthing run.
  long runs = 0;
  for (const char* sub : {"zigzag", "turning", "random"})
    for (const auto& e : fs::directory_iterator(data / "esso-osaka" / sub))
      runs += e.path().extension() == ".csv";
  EXPECT_EQ(static_cast<long>(names.size()), runs - 8);
  EXPECT_THAT(names, ::testing::Contains("zigzag_from_the_paper"));
  EXPECT_THAT(names, ::testing::Contains("zigzag 31-Jul 13:04"));
  const auto added = std::find(names.begin(), names.end(), "zigzag_from_the_paper");
  const SuiteData& run = esso.suite.test_data[added - names.begin()];
  EXPECT_EQ(run.format, "csv-log");
  EXPECT_EQ(run.map, esso.suite.test_data.front().map);
  EXPECT_EQ(run.end_at_stop, "n");  // as every listed test run: the recovery is dropped
  // Re-run closed-loop as the record says: 13:04 is the study's zigzag:20/20.
  EXPECT_EQ(run.maneuver, "zigzag:20/20");
  // The further runs are named by their file's stem (a listed run by the study's name).
  for (const SuiteData& d : esso.suite.test_data) {
    if (d.name.starts_with("turn_")) {
      EXPECT_THAT(d.maneuver, ::testing::MatchesRegex("turning:-?(20|35)")) << d.name;
    }
    if (d.name.starts_with("random_")) {
      EXPECT_EQ(d.maneuver, "") << d.name;
    }
  }
  EXPECT_THAT(esso.notes[0],
              HasSubstr(std::to_string(runs - 16) + " further runs of the data folder"));
  // The embedded vessel file is written beside the results, and the track names it there.
  ASSERT_EQ(esso.suite.vessels.size(), 1u);
  EXPECT_EQ(esso.suite.vessels[0], (dir / "out" / "esso-osaka.yaml").string());
  EXPECT_TRUE(fs::exists(dir / "out" / "esso-osaka.yaml"));
  for (const SuiteData& d : esso.suite.train_data)
    for (const std::string& f : d.files) EXPECT_TRUE(fs::exists(f)) << f;
}

// Cross-validated (--cv runs), a track's runs are its training files and its test runs, the
// further runs among them. Each is read as the test runs are (Esso Osaka's ended where the
// propeller stopped), a zig-zag or turn among the training files re-run closed-loop as its record
// says, and the cut copy of a run the folder holds whole is no run of its own. KVLCC2 is judged
// over both tanks' runs at once where the folder holds both: one track of MARIN's three and HSVA's
// nine, each left out in turn, in the place of each tank's own.
TEST(RealSuiteTest, CrossValidatedTracksLeaveOutEveryRunOfTheFolder) {
  if (!fs::exists(kShared / "esso-osaka") || !fs::exists(kShared / "kvlcc2-marin"))
    GTEST_SKIP() << "shared data absent: " << kShared;
  const fs::path dir = TempDir("cv");
  const std::vector<SuiteTrack> plain = RealSuiteTracks(kShared.string(), (dir / "p").string());
  const std::vector<SuiteTrack> tracks =
      RealSuiteTracks(kShared.string(), (dir / "cv").string(), "runs");
  // KVLCC2 and Esso Osaka; the cross-facility tracks train in one tank and score in the other by
  // design, and are not cross-validated.
  ASSERT_EQ(tracks.size(), 2u);
  const Suite& kvlcc2 = tracks[0].suite;
  EXPECT_TRUE(kvlcc2.cv.On());
  if (fs::exists(kShared / "kvlcc2-hsva")) {
    EXPECT_EQ(tracks[0].name, "kvlcc2-both-tanks");
    const std::vector<std::string> runs = TestNames(kvlcc2);
    ASSERT_EQ(runs.size(), 12u);
    EXPECT_THAT(std::vector<std::string>(runs.begin(), runs.begin() + 4),
                ::testing::ElementsAre("MARIN zigzag 20/-20", "MARIN zigzag -20/20",
                                       "MARIN turning 35", "HSVA zigzag 20/10 S"));
    // HSVA's training run too is read as its header names it.
    EXPECT_EQ(kvlcc2.test_data[3].maneuver, "zigzag:20/10");
    EXPECT_EQ(kvlcc2.test_data[3].format, "hsva-dat");
    EXPECT_EQ(kvlcc2.train_maneuvers.size(), 12u);
    // GP and SINDy are judged on both tanks; diagnose, hybrid and grey-box GP (a minute a fold)
    // are not run over the folds.
    std::vector<std::string> methods;
    for (const SuiteMethod& m : kvlcc2.methods) methods.push_back(m.Label());
    EXPECT_THAT(methods, ::testing::Contains("gp[+,-,*,abs]"));
    EXPECT_THAT(methods, ::testing::Contains("sindy"));
    for (const std::string& m : methods) {
      EXPECT_THAT(m, ::testing::Not(HasSubstr("vessel"))) << "grey-box GP cross-validated";
      EXPECT_THAT(m, ::testing::Not(::testing::AnyOf("diagnose", "hybrid")));
    }
    EXPECT_THAT(::testing::PrintToString(tracks[0].notes),
                HasSubstr("MARIN's 3 runs and HSVA's 9, each left out in turn"));
  } else {
    EXPECT_EQ(tracks[0].name, "kvlcc2");
    EXPECT_THAT(TestNames(kvlcc2),
                ::testing::ElementsAre("zigzag 20/-20", "zigzag -20/20", "turning 35"));
  }
  // MARIN's zz_20 reads as zigzag:-20/20 (maneuver_of_record_test).
  EXPECT_EQ(kvlcc2.test_data[0].maneuver, "zigzag:-20/20");

  const Suite& esso = tracks[1].suite;
  const std::vector<std::string> names = TestNames(esso);
  // Every run of the plain track, its eight training files split, but the cut copy of 15:58.
  EXPECT_EQ(names.size(), plain[1].suite.test_maneuvers.size() + 8 - 1);
  EXPECT_THAT(names, ::testing::Contains("8 runs: zigzag_31-Jul-2020_13_14_21"));
  EXPECT_THAT(names, ::testing::Contains("turn_14-Sep-2020_15_58_08"));
  EXPECT_THAT(names, ::testing::Not(::testing::Contains("turn_cut_14-Sep-2020_15_58_08")));
  EXPECT_THAT(names, ::testing::Contains("turn_cut_14-Sep-2020_16_09_02"));  // alone
  for (const SuiteData& d : esso.test_data) {
    EXPECT_EQ(d.end_at_stop, "n") << d.name;
    ASSERT_EQ(d.files.size(), 1u) << d.name;
    if (d.name.starts_with("8 runs: zigzag_") || d.name.starts_with("8 runs: turn_")) {
      EXPECT_THAT(d.maneuver, ::testing::MatchesRegex("(zigzag|turning):.*")) << d.name;
    }
    if (d.name.starts_with("8 runs: random_")) {
      EXPECT_EQ(d.maneuver, "") << d.name;
    }
  }
  // A fold trains on nearly all of the folder's rows, about four times the track's own training
  // part: each fold's refit fits at most 20000 of them, spread over its runs.
  auto refit_rows = [](const Suite& s) -> nlohmann::json {
    for (const SuiteMethod& m : s.methods)
      if (m.method == "refit") return m.options.value("fit_rows", nlohmann::json());
    return "no refit";
  };
  EXPECT_EQ(refit_rows(esso), 20000);
  EXPECT_EQ(refit_rows(plain[1].suite), nlohmann::json());  // all 30642 rows without --cv
  const std::string notes = ::testing::PrintToString(tracks[1].notes);
  EXPECT_THAT(notes, HasSubstr("each fold's refit fits at most 20000 rows"));
  EXPECT_THAT(notes, HasSubstr("a cut copy of 'turn_14-Sep-2020_15_58_08'"));
  EXPECT_THAT(notes, HasSubstr("cross-validation over " + std::to_string(names.size()) + " runs"));
}

// Without --cv, KVLCC2 of both tanks is a track where a further run of either tank's folder can
// score it: trained on all twelve shared runs jointly (each named with its tank, the training runs
// with the tests their records hold), scored on the further runs. With the shared runs alone it
// has nothing held out, and MARIN's track says so.
TEST(RealSuiteTest, BothTanksTrainOnEverySharedRunAndScoreTheFurtherOnes) {
  if (!fs::exists(kShared / "kvlcc2-hsva") || !fs::exists(kShared / "kvlcc2-marin"))
    GTEST_SKIP() << "shared data absent: " << kShared;
  const fs::path dir = TempDir("tanks");
  const fs::path data = dir / "data";
  for (const char* tank : {"kvlcc2-marin", "kvlcc2-hsva"}) {
    fs::create_directories(data / tank);
    for (const auto& e : fs::directory_iterator(kShared / tank))
      fs::create_symlink(fs::absolute(e.path()), data / tank / e.path().filename());
  }
  const std::vector<SuiteTrack> shared_only =
      RealSuiteTracks(data.string(), (dir / "out1").string());
  for (const SuiteTrack& t : shared_only) EXPECT_NE(t.name, "kvlcc2-both-tanks");
  EXPECT_THAT(::testing::PrintToString(shared_only.at(0).notes),
              HasSubstr("kvlcc2-both-tanks not run: no further run"));

  fs::create_symlink(fs::absolute(kShared / "kvlcc2-hsva/HSVA_CPMC_KVLCC2_Z_20_05.dat"),
                     data / "kvlcc2-hsva/HSVA_held_out_20_05.dat");
  const std::vector<SuiteTrack> tracks = RealSuiteTracks(data.string(), (dir / "out2").string());
  const auto both = std::find_if(tracks.begin(), tracks.end(),
                                 [](const SuiteTrack& t) { return t.name == "kvlcc2-both-tanks"; });
  ASSERT_NE(both, tracks.end());
  const Suite& suite = both->suite;
  EXPECT_FALSE(suite.cv.On());
  ASSERT_EQ(suite.train_data.size(), 12u);
  EXPECT_EQ(suite.train_data[0].name, "MARIN zigzag 20/-20");
  EXPECT_EQ(suite.train_data[0].maneuver, "zigzag:-20/20");  // read from the record
  EXPECT_EQ(suite.train_data[3].name, "HSVA zigzag 20/10 S");
  EXPECT_EQ(suite.train_data[3].maneuver, "zigzag:20/10");
  EXPECT_EQ(suite.train_data[3].format, "hsva-dat");
  EXPECT_THAT(TestNames(suite), ::testing::ElementsAre("HSVA_held_out_20_05"));
  EXPECT_EQ(suite.test_data[0].maneuver, "zigzag:20/5");
  EXPECT_EQ(suite.test_data[0].format, "hsva-dat");
  EXPECT_THAT(::testing::PrintToString(both->notes),
              HasSubstr("trained on jointly, scored on 1 further run of the two folders"));
}

}  // namespace
}  // namespace usvid
