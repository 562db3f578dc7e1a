// A vessel resolved once where it is named (simulation/vessel_ref.h): the name kept as given, the
// simulator found then, a bad name refused then (not at the first use deep in a fit), and a
// vessel file read once however many references name it.
#include "simulation/vessel_ref.h"

#include <gtest/gtest.h>

#include <string>

#include "core/error.h"

namespace usvid {
namespace {

const std::string kKvlcc2File = std::string(USVID_SOURCE_DIR) + "/docs/vessels/files/kvlcc2.yaml";

TEST(VesselRefTest, ACompiledVesselIsFoundWhereItIsNamed) {
  const VesselRef odin("odin-hs");
  ASSERT_FALSE(odin.empty());
  EXPECT_EQ(odin.Name(), "odin-hs");
  EXPECT_EQ(&odin.Simulator(), &FindVessel("odin-hs"));
  EXPECT_EQ(odin.Info().name, "odin-hs");
}

TEST(VesselRefTest, NoNameIsNoVessel) {
  EXPECT_TRUE(VesselRef().empty());
  EXPECT_TRUE(VesselRef("").empty());
  EXPECT_EQ(VesselRef().Name(), "");
}

TEST(VesselRefTest, AnUnknownNameIsRefusedWhereItIsNamed) {
  try {
    const VesselRef ref("titanic");
    ADD_FAILURE() << "an unknown vessel was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'titanic': unknown vessel"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(VesselRef("no/such/vessel.yaml"), InputError);
}

TEST(VesselRefTest, AVesselFileIsReadOnceForEveryReference) {
  const VesselRef a(kKvlcc2File), b(kKvlcc2File);
  EXPECT_EQ(&a.Simulator(), &b.Simulator());
  EXPECT_EQ(a, b);
  EXPECT_EQ(a.Name(), kKvlcc2File);  // the path as given, for model.json
  EXPECT_EQ(a.Info().name, "kvlcc2-file");  // the file's name: for a reader
  EXPECT_FALSE(a == VesselRef("kvlcc2"));  // the compiled-in KVLCC2 is another vessel
}

}  // namespace
}  // namespace usvid
