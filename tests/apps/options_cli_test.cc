// `usvid methods`: every method with the options it declares, and docs/options.md, which must
// be exactly what `usvid methods --markdown` prints (the page is generated, never hand-edited).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "tests/apps/run_usvid.h"

namespace usvid {
namespace {

using ::testing::HasSubstr;
using testing::RunUsvid;

TEST(OptionsCliTest, ListsEveryMethodWithItsOptions) {
  const auto r = RunUsvid("methods");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("gp: GP-SR"));
  EXPECT_THAT(r.out, HasSubstr("  max_depth (--max-depth): a whole number in [2, 17]; default 6"));
  EXPECT_THAT(r.out, HasSubstr("  threshold (--threshold): a finite number >= 0; default none"));
  EXPECT_THAT(r.out, HasSubstr("  library (--library): a list of constant, products, abs"));
}

TEST(OptionsCliTest, TheOptionsPageIsTheDeclarations) {
  const auto r = RunUsvid("methods --markdown");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream page(std::string(USVID_SOURCE_DIR) + "/docs/options.md");
  ASSERT_TRUE(page) << "docs/options.md is missing";
  std::stringstream text;
  text << page.rdbuf();
  EXPECT_EQ(text.str(), r.out)
      << "docs/options.md is out of date: ./build/usvid methods --markdown > docs/options.md";
}

}  // namespace
}  // namespace usvid
