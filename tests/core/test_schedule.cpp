#include <gtest/gtest.h>

#include "core/schedule.hpp"

namespace cortex {
namespace {

TEST(Schedule, InterpolatesLinearlyAndHoldsAtBothEnds) {
  const Schedule s({{1.0, 10.0}, {3.0, 20.0}, {4.0, 0.0}});
  EXPECT_DOUBLE_EQ(s.at(0.0), 10.0);
  EXPECT_DOUBLE_EQ(s.at(1.0), 10.0);
  EXPECT_DOUBLE_EQ(s.at(2.0), 15.0);
  EXPECT_DOUBLE_EQ(s.at(3.5), 10.0);
  EXPECT_DOUBLE_EQ(s.at(4.0), 0.0);
  EXPECT_DOUBLE_EQ(s.at(100.0), 0.0);
  EXPECT_FALSE(s.isZero());
  EXPECT_FALSE(s.isConstant());
}

TEST(Schedule, ConstantAndUnset) {
  EXPECT_DOUBLE_EQ(Schedule(2.5).at(7.0), 2.5);
  EXPECT_TRUE(Schedule(0.0).isZero());
  EXPECT_FALSE(Schedule().isSet());
  EXPECT_TRUE(Schedule(1.0).isSet());
}

}  // namespace
}  // namespace cortex
