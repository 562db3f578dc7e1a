// The maneuver a log's header names (metrics/maneuver_header.h): HSVA's KVLCC2 headers, with and
// without the side, usvid's own specs and a turning circle's name give their angles and side; a
// name usvid does not know, or an angle out of range, is refused naming the file and the text.
#include "metrics/maneuver_header.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/error.h"

namespace usvid {
namespace {

void ExpectManeuver(const std::string& text, const std::string& kind, double a, double b,
                    int side) {
  const NamedManeuver m = ParseManeuverHeader(text, "F.dat");
  EXPECT_EQ(m.kind, kind) << text;
  EXPECT_DOUBLE_EQ(m.rudder_deg, a) << text;
  EXPECT_DOUBLE_EQ(m.check_deg, b) << text;
  EXPECT_EQ(m.side, side) << text;
}

TEST(ManeuverHeaderTest, HsvasHeadersGiveTheirAnglesAndSide) {
  ExpectManeuver("Z20°/10° starting to starboard", "zigzag", 20, 10, 1);
  ExpectManeuver(" Z10°/10° starting to port ", "zigzag", 10, 10, -1);
  ExpectManeuver("Z10°/1°", "zigzag", 10, 1, 0);
  ExpectManeuver("Z30°/05°", "zigzag", 30, 5, 0);
  ExpectManeuver("zig-zag 20/20 deg to port", "zigzag", 20, 20, -1);
}

TEST(ManeuverHeaderTest, UsvidSpecsAndTurningCirclesAreNamesToo) {
  ExpectManeuver("zigzag:-20/10", "zigzag", 20, 10, -1);
  ExpectManeuver("zigzag:35/5", "zigzag", 35, 5, 1);
  ExpectManeuver("turning:-35", "turning", 35, 0, -1);
  ExpectManeuver("T35° to port", "turning", 35, 0, -1);
  ExpectManeuver("Turning circle 35 deg starboard", "turning", 35, 0, 1);
}

TEST(ManeuverHeaderTest, UnknownNamesAndAnglesOutOfRangeAreRefusedNamingTheFile) {
  for (const char* text : {"Williamson turn", "Time series of motions", "Z20°", "zigzag:20/0",
                           "Z120°/10°", ""})
    EXPECT_THAT([&] { ParseManeuverHeader(text, "runs/F.dat"); },
                testing::ThrowsMessage<InputError>(testing::HasSubstr("runs/F.dat: the maneuver '")))
        << text;
}

}  // namespace
}  // namespace usvid
