// A maneuver spec's name and numbers (maneuvers/maneuver_spec.h), and the same test to the other
// side: what the closed-loop replay tells a user who gave a zig-zag or a turn the wrong way round.
#include "maneuvers/maneuver_spec.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/error.h"

namespace usvid {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

TEST(ManeuverSpecTest, ANameAndItsNumbers) {
  const ManeuverSpec z = ParseManeuverSpec("zigzag:-20/15");
  EXPECT_EQ(z.name, "zigzag");
  EXPECT_THAT(z.numbers, ElementsAre(-20.0, 15.0));
  const ManeuverSpec t = ParseManeuverSpec("turning");
  EXPECT_EQ(t.name, "turning");
  EXPECT_TRUE(t.numbers.empty());
  EXPECT_THAT(ParseManeuverSpec("random-steps:2.5").numbers, ElementsAre(2.5));
}

TEST(ManeuverSpecTest, TheMirrorTurnsTheFirstNumbersSignAsWritten) {
  EXPECT_EQ(ParseManeuverSpec("zigzag:-20/20").Mirrored(), "zigzag:20/20");
  EXPECT_EQ(ParseManeuverSpec("zigzag:10/5").Mirrored(), "zigzag:-10/5");
  EXPECT_EQ(ParseManeuverSpec("turning:35").Mirrored(), "turning:-35");
  EXPECT_EQ(ParseManeuverSpec("zigzag").Mirrored(), "zigzag:-20/20");
  EXPECT_EQ(ParseManeuverSpec("turning").Mirrored(), "turning:-35");
}

// The kind, the angles with the ITTC defaults (20/20, 35) and the side, from one parse; the kind
// alone from the name, never throwing, for text that may not be a maneuver at all.
TEST(ManeuverSpecTest, TheKindTheAnglesAndTheSide) {
  const ManeuverSpec z = ParseManeuverSpec("zigzag:-20/10");
  EXPECT_EQ(z.kind, ManeuverKind::kZigzag);
  EXPECT_TRUE(z.IsTest());
  EXPECT_EQ(z.RudderDeg(), 20.0);
  EXPECT_EQ(z.CheckDeg(), 10.0);
  EXPECT_EQ(z.Side(), -1);
  const ManeuverSpec bare = ParseManeuverSpec("zigzag");
  EXPECT_EQ(bare.RudderDeg(), kDefaultZigzagDeg);
  EXPECT_EQ(bare.CheckDeg(), kDefaultZigzagDeg);
  EXPECT_EQ(bare.Side(), 1);
  const ManeuverSpec t = ParseManeuverSpec("turning");
  EXPECT_EQ(t.kind, ManeuverKind::kTurning);
  EXPECT_EQ(t.RudderDeg(), kDefaultTurningDeg);
  EXPECT_EQ(ParseManeuverSpec("turning:-25").Side(), -1);
  EXPECT_EQ(ParseManeuverSpec("stepgrid:4/3/25").kind, ManeuverKind::kStepGrid);
  EXPECT_FALSE(ParseManeuverSpec("random-steps").IsTest());
  EXPECT_EQ(ParseManeuverSpec("spiral:3").kind, ManeuverKind::kUnknown);
  EXPECT_EQ(KindOfManeuver("autopilot:a/b"), ManeuverKind::kAutopilot);
  EXPECT_EQ(KindOfManeuver("zigzagging"), ManeuverKind::kUnknown);
  EXPECT_TRUE(IsManeuverTest("turning:35"));
  EXPECT_FALSE(IsManeuverTest("prbs"));
  EXPECT_TRUE(IsBareManeuverTest("zigzag"));
  EXPECT_FALSE(IsBareManeuverTest("zigzag:20/20"));
  EXPECT_FALSE(IsBareManeuverTest("multisine"));
}

TEST(ManeuverSpecTest, ANumberThatDoesNotParseNamesTheSpec) {
  for (const char* bad : {"zigzag:a/b", "zigzag:", "turning:35/", "zigzag:20//20"}) {
    try {
      ParseManeuverSpec(bad);
      ADD_FAILURE() << bad << " was accepted";
    } catch (const InputError& e) {
      EXPECT_THAT(e.what(), HasSubstr(std::string("--maneuver '") + bad + "'"));
    }
  }
}

}  // namespace
}  // namespace usvid
