// Motion keys: decomposition into translation, rotation and stretch, interpolation, and the swept bounds
// the accelerators index moving objects by.
#include "snell/scene/motion.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "snell/math/constants.hpp"

namespace snell::scene {
namespace {

using math::Transform;
using math::Vec3;

void expect_near(const Vec3& a, const Vec3& b, double tol = 1e-12) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

TEST(Motion, DecomposeAndComposeRoundTrip) {
  const Transform t = Transform::translate({1, -2, 3}) * Transform::rotate_xyz_degrees({20, 35, -70}) *
                      Transform::scale({2, 0.5, -3});  // the negative scale is a reflection
  const auto back = compose(decompose(t));
  ASSERT_TRUE(back);
  for (const Vec3& p : {Vec3(1, 0, 0), Vec3(0.3, -4, 2), Vec3(-1, 1, 1)})
    expect_near(back->point(p), t.point(p), 1e-10);
}

TEST(Motion, RotationIsSlerpedNotLerped) {
  // Half way between no rotation and 90 degrees about y is 45 degrees: a unit vector stays unit length
  // (a matrix lerp would shrink it to cos 45 = 0.707).
  const Pose a = decompose(Transform{});
  const Pose b = decompose(Transform::rotate_xyz_degrees({0, 90, 0}));
  const auto half = compose(interpolate(a, b, 0.5));
  ASSERT_TRUE(half);
  expect_near(half->vector({1, 0, 0}), Transform::rotate_xyz_degrees({0, 45, 0}).vector({1, 0, 0}));
}

TEST(Motion, TranslationAndScaleAreLinear) {
  const Pose a = decompose(Transform::scale({1, 1, 1}));
  const Pose b = decompose(Transform::translate({4, 0, 0}) * Transform::scale({3, 1, 1}));
  const auto quarter = compose(interpolate(a, b, 0.25));
  expect_near(quarter->point({1, 1, 1}), {1 + 0.25 * (3 - 1) + 1, 1, 1});
}

TEST(Motion, KeysHoldBeforeTheFirstAndAfterTheLast) {
  MotionLayer layer;
  layer.keys = {{0.2, decompose(Transform::translate({1, 0, 0}))},
                {0.6, decompose(Transform::translate({3, 0, 0}))}};
  expect_near(layer.keyed(0)->point({}), {1, 0, 0});
  expect_near(layer.keyed(0.4)->point({}), {2, 0, 0});
  expect_near(layer.keyed(1)->point({}), {3, 0, 0});
}

TEST(Motion, FrameMovesTheCentreOfRotation) {
  // motion { rotate y*90 } followed by translate x*5: the object spins about its own centre at x = 5.
  MotionLayer layer;
  layer.keys = {{0, Pose{}}, {1, decompose(Transform::rotate_xyz_degrees({0, 90, 0}))}};
  layer.frame = Transform::translate({5, 0, 0});
  const Motion motion({layer});
  expect_near(motion.at(1)->point({5, 0, 0}), {5, 0, 0});
  expect_near(motion.at(1)->point({6, 0, 0}), {5, 0, -1});  // POV-Ray's left-handed rotate: +x to -z
}

TEST(Motion, SweptBoundsHoldTheObjectAtEveryTime) {
  MotionLayer layer;
  layer.keys = {
      {0, Pose{}},
      {0.5, decompose(Transform::translate({2, 1, 0}) * Transform::rotate_xyz_degrees({0, 0, 120}))},
      {1, decompose(Transform::translate({-1, 0, 3}) * Transform::scale({2, 2, 0.5}))}};
  layer.frame = Transform::translate({0.5, 0, 0});
  const Motion motion({layer});
  const math::Bounds3 still({-0.5, -0.25, -1}, {1.5, 0.25, 1});
  const math::Bounds3 swept = motion.swept(still);
  for (int i = 0; i <= 400; ++i) {
    const auto d = motion.at(i / 400.0);
    ASSERT_TRUE(d);
    const math::Bounds3 moved = d->bounds(still);
    EXPECT_TRUE(swept.contains(moved.lo) && swept.contains(moved.hi)) << "t = " << i / 400.0;
  }
  // Pure translation is bounded tightly: the union of the boxes at the keys.
  MotionLayer slide;
  slide.keys = {{0, Pose{}}, {1, decompose(Transform::translate({3, 0, 0}))}};
  const math::Bounds3 s = Motion({slide}).swept(still);
  EXPECT_NEAR(s.lo.x, -0.5, 1e-6);
  EXPECT_NEAR(s.hi.x, 4.5, 1e-6);
  EXPECT_NEAR(s.hi.y, 0.25, 1e-6);
}

}  // namespace
}  // namespace snell::scene
