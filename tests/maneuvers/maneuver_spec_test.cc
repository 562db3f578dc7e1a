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
  EXPECT_EQ(ParseManeuverSpec("zigzag:-20/20").Mirrored("20/20"), "zigzag:20/20");
  EXPECT_EQ(ParseManeuverSpec("zigzag:10/5").Mirrored("20/20"), "zigzag:-10/5");
  EXPECT_EQ(ParseManeuverSpec("turning:35").Mirrored("35"), "turning:-35");
  EXPECT_EQ(ParseManeuverSpec("zigzag").Mirrored("20/20"), "zigzag:-20/20");
  EXPECT_EQ(ParseManeuverSpec("turning").Mirrored("35"), "turning:-35");
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
