// Where GP validates (methods/gp/validation_split.h): one record keeps its last share as it
// is; records joined for one fit are validated on the last share of each, so that a joint fit
// of a random run, turns and zig-zags is not chosen on the last zig-zag's end alone, and the
// pieces stay apart, each after a gap.
#include <gtest/gtest.h>

#include "core/records.h"
#include "core/stretches.h"
#include "methods/gp/validation_split.h"

namespace usvid::gp {
namespace {

// `rows` samples at 10 Hz whose channel x counts from `first`.
Dataset Counting(int rows, double first) {
  Dataset d(Eigen::VectorXd::LinSpaced(rows, 0.0, 0.1 * (rows - 1)));
  d.Set("x", Eigen::VectorXd::LinSpaced(rows, first, first + rows - 1));
  return d;
}

TEST(GpValidationSplitTest, OneRecordStaysAsItIs) {
  PreparedData p;
  p.data = Counting(100, 0);
  EXPECT_FALSE(SplitForValidation(p, 0.2).reordered);
}

TEST(GpValidationSplitTest, JoinedRecordsAreValidatedOnTheLastShareOfEach) {
  PreparedData p;
  p.data = JoinRecords({Counting(100, 0), Counting(50, 1000), Counting(3, 5000)});
  const ValidationSplit s = SplitForValidation(p, 0.2);
  ASSERT_TRUE(s.reordered);
  const Dataset& d = s.reordered->data;
  ASSERT_EQ(d.rows(), 153);
  EXPECT_EQ(s.train_rows, 80 + 40 + 3);  // the 3-row record is too short to split: all fitted
  const Eigen::VectorXd& x = d["x"];
  EXPECT_EQ(x(0), 0);
  EXPECT_EQ(x(79), 79);
  EXPECT_EQ(x(80), 1000);
  EXPECT_EQ(x(120), 5000);
  EXPECT_EQ(x(123), 80);    // the validation part: the first record's last 20 rows
  EXPECT_EQ(x(143), 1040);  // then the second's last 10
  EXPECT_EQ(x(152), 1049);
  // Five pieces, each after a gap: no simulation runs from one into the next.
  EXPECT_EQ(Stretches(d.t(), kGridGapFactor).size(), 5u);
}

}  // namespace
}  // namespace usvid::gp
