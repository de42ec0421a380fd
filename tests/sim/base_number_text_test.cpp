// Numbers as text: exact round trips and strict whole-text parsing.

#include "sim/base/number_text.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <string>

namespace tactip {
namespace {

TEST(NumberTextTest, RoundTripTextIsShortestAndReadsBackExactly) {
  EXPECT_EQ(RoundTripText(0.1), "0.1");
  EXPECT_EQ(RoundTripText(0.1f), "0.1");
  EXPECT_EQ(RoundTripText(1e-300), "1e-300");
  for (const double v : {1.0 / 3.0, -2.5e-7, std::numeric_limits<double>::max(), 5e-324}) {
    double back = 0.0;
    ASSERT_TRUE(ParseWhole(RoundTripText(v), back)) << RoundTripText(v);
    EXPECT_EQ(back, v);
  }
  float back = 0.0f;
  ASSERT_TRUE(ParseWhole(RoundTripText(1.0f / 3.0f), back));
  EXPECT_EQ(back, 1.0f / 3.0f);
}

TEST(NumberTextTest, ParseWholeTakesTheWholeTextOrNothing) {
  long long i = 7;
  EXPECT_TRUE(ParseWhole("-12", i));
  EXPECT_EQ(i, -12);
  for (const std::string bad : {"", " 1", "1 ", "1x", "+1", "0x10", "99999999999999999999"}) {
    EXPECT_FALSE(ParseWhole(bad, i)) << "'" << bad << "'";
  }
  std::uint64_t u = 0;
  EXPECT_FALSE(ParseWhole("-1", u));
  double d = 0.0;
  EXPECT_TRUE(ParseWhole("2.5e3", d));
  EXPECT_EQ(d, 2500.0);
  EXPECT_FALSE(ParseWhole("2.5.", d));
}

}  // namespace
}  // namespace tactip
