// The closure range takes the channel's extremes, open first, and ignores NaN.
#include "calibration/closure_range.h"

#include "tracking/frame_assembler.h"

#include <gtest/gtest.h>

#include <cmath>

namespace microsim::calibration {
namespace {

TEST(ClosureRange, OpenIsTheExtremeNearerTheFirstReading) {
  ClosureRange range;
  EXPECT_FALSE(range.usable(1.0));
  // a sensor that reads high when open: 900 at rest, squeezed down to 120
  for (double v : {880.0, 900.0, 700.0, 300.0, 120.0, 400.0, std::nan(""), 890.0}) range.add(v);
  EXPECT_EQ(range.count(), 7);
  EXPECT_DOUBLE_EQ(range.open(), 900.0);
  EXPECT_DOUBLE_EQ(range.closed(), 120.0);
  EXPECT_TRUE(range.usable(100.0));
  EXPECT_FALSE(range.usable(1000.0));

  // mapped through the frame assembler's equation: open → 0, closed → 1
  tracking::HandMapping hand;
  hand.closureOpen = range.open();
  hand.closureClosed = range.closed();
  EXPECT_DOUBLE_EQ(tracking::closureFromChannel(hand, 900.0), 0.0);
  EXPECT_DOUBLE_EQ(tracking::closureFromChannel(hand, 120.0), 1.0);
  EXPECT_DOUBLE_EQ(tracking::closureFromChannel(hand, 510.0), 0.5);

  range.reset();
  range.add(0.1);
  range.add(0.9);
  EXPECT_DOUBLE_EQ(range.open(), 0.1);
  EXPECT_DOUBLE_EQ(range.closed(), 0.9);
}

}  // namespace
}  // namespace microsim::calibration
