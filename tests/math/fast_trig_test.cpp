// fast_sin / fast_cos against glibc's sin and cos and against exact values.
#include "snell/math/fast_trig.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "snell/math/constants.hpp"

namespace snell::math {
namespace {

TEST(FastTrig, MatchesLibmToAboutOneUlp) {
  double worst = 0;
  for (int i = -200000; i <= 200000; ++i) {
    const double x = i * 1.83e-4;  // [-36.6, 36.6], many quadrants
    worst = std::max(worst, std::fabs(fast_sin(x) - std::sin(x)));
    worst = std::max(worst, std::fabs(fast_cos(x) - std::cos(x)));
  }
  EXPECT_LE(worst, 4.5e-16);
  // Far arguments, where the reduction has most to cancel.
  for (double x : {1234.5678, -9876.54321, 99999.9}) {
    EXPECT_NEAR(fast_sin(x), std::sin(x), 1e-12) << x;
    EXPECT_NEAR(fast_cos(x), std::cos(x), 1e-12) << x;
  }
}

TEST(FastTrig, ExactValuesAndSpecialArguments) {
  EXPECT_EQ(fast_sin(0.0), 0.0);
  EXPECT_EQ(fast_cos(0.0), 1.0);
  EXPECT_NEAR(fast_sin(kPi / 6), 0.5, 2.3e-16);  // within an ulp or so of the exact value
  EXPECT_NEAR(fast_cos(kPi / 3), 0.5, 2.3e-16);  // within an ulp or so of the exact value
  EXPECT_NEAR(fast_sin(kPi / 2), 1.0, 2.3e-16);  // within an ulp or so of the exact value
  EXPECT_NEAR(fast_cos(kPi), -1.0, 2.3e-16);     // within an ulp or so of the exact value
  EXPECT_NEAR(fast_sin(-3 * kPi / 2), 1.0, 1e-15);
  EXPECT_TRUE(std::isnan(fast_sin(std::numeric_limits<double>::quiet_NaN())));
  EXPECT_TRUE(std::isnan(fast_cos(std::numeric_limits<double>::infinity())));
  EXPECT_DOUBLE_EQ(fast_sin(1e6), std::sin(1e6));  // beyond the reduction's range: libm
}

}  // namespace
}  // namespace snell::math
