#include "seaflex/model/time_signal.hpp"

#include <gtest/gtest.h>

using namespace seaflex;

TEST(TimeSignal, ConstantRampTable) {
  EXPECT_EQ(TimeSignal::constant(2.5)(100.0), 2.5);
  const auto ramp = TimeSignal::ramp(5.0, 30.0);
  EXPECT_EQ(ramp(0.0), 0.0);
  EXPECT_EQ(ramp(5.0), 0.0);
  EXPECT_DOUBLE_EQ(ramp(20.0), 0.5);
  EXPECT_EQ(ramp(35.0), 1.0);
  EXPECT_EQ(ramp(99.0), 1.0);
  const auto table = TimeSignal::table({0.0, 1.0, 3.0}, {0.0, 2.0, -2.0});
  EXPECT_EQ(table(-1.0), 0.0);
  EXPECT_DOUBLE_EQ(table(0.5), 1.0);
  EXPECT_DOUBLE_EQ(table(2.0), 0.0);
  EXPECT_EQ(table(10.0), -2.0);
  // a zero-length ramp is a step
  EXPECT_EQ(TimeSignal::ramp(1.0, 0.0)(1.0 + 1e-12), 1.0);
}

TEST(TimeSignal, RejectsBadTables) {
  EXPECT_THROW(TimeSignal::table({0.0}, {1.0}), std::invalid_argument);
  EXPECT_THROW(TimeSignal::table({0.0, 0.0}, {1.0, 2.0}), std::invalid_argument);
  EXPECT_THROW(TimeSignal::ramp(0.0, -1.0), std::invalid_argument);
}

TEST(VectorSignal, ScaledVectorAndTable) {
  const VectorSignal v(Vec3(1, 2, 3), TimeSignal::ramp(0.0, 2.0));
  EXPECT_TRUE(v(1.0).isApprox(Vec3(0.5, 1.0, 1.5)));
  const auto t = VectorSignal::table({0.0, 2.0}, {Vec3(0, 0, 0), Vec3(2, 4, 6)});
  EXPECT_TRUE(t(1.0).isApprox(Vec3(1, 2, 3)));
  EXPECT_TRUE(t(5.0).isApprox(Vec3(2, 4, 6)));
}
