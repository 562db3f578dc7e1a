// `usvid preprocess` as a user runs it: the delay found and taken out, derivatives written,
// bad channels and options refused with exit code 2.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/csv_dataset.h"
#include "tests/apps/run_usvid.h"

namespace usvid {
namespace {

using testing::FreshTempDir;
using ::testing::HasSubstr;
using testing::RunUsvid;

class PreprocessCliTest : public ::testing::Test {};

// `usvid preprocess` as a user runs it: the delay found and taken out, derivatives written.
TEST_F(PreprocessCliTest, FindsTheDelayAndWritesDerivatives) {
  const auto dir = FreshTempDir();
  const auto data = (dir / "d.csv").string(), out = (dir / "p.csv").string();
  ASSERT_EQ(RunUsvid("simulate --vessel odin3dof --maneuver random-steps --duration 300 "
                     "--effect input_delay=0.6 --noise 0.01 --out " +
                     data)
                .exit_code,
            0);
  const auto r = RunUsvid("preprocess --data " + data +
                          " --states u,v,r --inputs "
                          "tau_x,tau_y,tau_n --delay auto --out " +
                          out);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("inputs shifted by 12 samples"));
  const Dataset p = ReadDatasetCsv(out);
  for (const char* c : {"u", "u_dot", "u_raw", "r_dot", "tau_n"}) EXPECT_TRUE(p.Has(c)) << c;
  const auto bad =
      RunUsvid("preprocess --data " + data + " --states u,w --inputs tau_x --out " + out);
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_THAT(bad.err, HasSubstr("no channel 'w'"));
  const auto delay = RunUsvid("preprocess --data " + data +
                              " --states u --inputs tau_x "
                              "--delay soon --out " +
                              out);
  EXPECT_EQ(delay.exit_code, 2);
  EXPECT_THAT(delay.err, HasSubstr("--delay 'soon'"));
}

}  // namespace
}  // namespace usvid
