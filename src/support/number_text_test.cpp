#include "duet/support/number_text.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

namespace duet {
namespace {

TEST(ShortestText, ReadsBackAsTheSameDoubleWithoutNoise) {
  EXPECT_EQ(shortest_text(0.05), "0.05");  // not 0.050000000000000003
  EXPECT_EQ(shortest_text(0.1 + 0.2), "0.30000000000000004");
  EXPECT_EQ(shortest_text(1e-7), "1e-07");
  EXPECT_EQ(shortest_text(10000), "10000");
  EXPECT_EQ(shortest_text(-2.5), "-2.5");
  EXPECT_EQ(shortest_text(-0.0), "-0");
  EXPECT_EQ(shortest_text(std::numeric_limits<double>::infinity()), "inf");
  EXPECT_EQ(shortest_text(-std::numeric_limits<double>::infinity()), "-inf");
  EXPECT_EQ(shortest_text(std::nan("")), "nan");
  const double smallest_normal = std::numeric_limits<double>::min();
  EXPECT_EQ(shortest_text(-smallest_normal), "-2.2250738585072014e-308");  // the longest: 24 characters
}

}  // namespace
}  // namespace duet
