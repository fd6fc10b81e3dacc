// math::is_finite(Vec3), which the BVH walk applies to every ray's origin and direction: true exactly when
// no component is infinite or NaN, whatever the others are (huge, tiny, signed zero).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "snell/math/vec3.hpp"

namespace {

using snell::math::is_finite;
using snell::math::Vec3;

TEST(Vec3FiniteTest, FalseForAnyInfiniteOrNanComponent) {
  const double inf = std::numeric_limits<double>::infinity(), nan = std::nan("");
  const double big = std::numeric_limits<double>::max(), tiny = std::numeric_limits<double>::denorm_min();
  EXPECT_TRUE(is_finite(Vec3{0, -0.0, 0}));
  EXPECT_TRUE(is_finite(Vec3{big, big, -big}));  // no overflow in the check
  EXPECT_TRUE(is_finite(Vec3{tiny, -tiny, 1}));
  for (int axis = 0; axis < 3; ++axis)
    for (const double bad : {inf, -inf, nan}) {
      Vec3 v{1, 2, 3};
      v[axis] = bad;
      EXPECT_FALSE(is_finite(v)) << "axis " << axis << " value " << bad;
    }
  EXPECT_FALSE(is_finite(Vec3{inf, -inf, 0}));
}

}  // namespace
