#include "snell/math/transform.hpp"

#include <gtest/gtest.h>

#include "snell/math/constants.hpp"

using namespace snell::math;

namespace {
void expect_near(const Vec3& a, const Vec3& b, double eps = 1e-12) {
  EXPECT_NEAR(a.x, b.x, eps);
  EXPECT_NEAR(a.y, b.y, eps);
  EXPECT_NEAR(a.z, b.z, eps);
}
}  // namespace

TEST(TransformTest, InverseUndoesCompositeTransform) {
  const Transform t = Transform::translate({1, -2, 3}) * Transform::rotate_xyz_degrees({30, 45, 60}) *
                      Transform::scale({2, 0.5, 3});
  const Vec3 p{0.3, -1.7, 2.2};
  expect_near(t.inverse_point(t.point(p)), p);
  expect_near(t.inverse().point(t.point(p)), p);
  const Matrix4 product = t.matrix() * t.inverse_matrix();
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) EXPECT_NEAR(product.m[i][j], i == j ? 1.0 : 0.0, 1e-12);
}

TEST(TransformTest, RotateFollowsPovRayLeftHandRule) {
  // POV-Ray documentation: `rotate <0,90,0>` turns +x into -z and +z into +x (left-hand rule about +y).
  const Transform ry = Transform::rotate_xyz_degrees({0, 90, 0});
  expect_near(ry.vector({1, 0, 0}), {0, 0, -1});
  expect_near(ry.vector({0, 0, 1}), {1, 0, 0});
  // About z by 90: +x becomes +y; about x by 90: +y becomes +z.
  expect_near(Transform::rotate_xyz_degrees({0, 0, 90}).vector({1, 0, 0}), {0, 1, 0});
  expect_near(Transform::rotate_xyz_degrees({90, 0, 0}).vector({0, 1, 0}), {0, 0, 1});
}

TEST(TransformTest, RotationOrderIsXThenYThenZ) {
  const Transform combined = Transform::rotate_xyz_degrees({90, 90, 0});
  const Transform stepwise = Transform::rotate_xyz_degrees({0, 90, 0}) * Transform::rotate_xyz_degrees({90, 0, 0});
  expect_near(combined.vector({0, 1, 0}), stepwise.vector({0, 1, 0}));
  // +y -> (x by 90) +z -> (y by 90) +x
  expect_near(combined.vector({0, 1, 0}), {1, 0, 0});
}

TEST(TransformTest, NormalsStayPerpendicularUnderNonUniformScale) {
  const Transform s = Transform::scale({4, 1, 1}) * Transform::rotate_xyz_degrees({0, 0, 30});
  const Vec3 tangent{1, 1, 0}, normal{1, -1, 0};
  EXPECT_NEAR(dot(s.vector(tangent), s.normal(normal)), 0.0, 1e-12);
}

TEST(TransformTest, SingularMatrixHasNoInverse) {
  Matrix4 m = Matrix4::identity();
  m.m[1][1] = 0;
  EXPECT_FALSE(Transform::from_matrix(m).has_value());
}

TEST(TransformTest, PovMatrixUsesRowVectorConvention) {
  // POV-Ray `matrix <1,0,0, 0,1,0, 0,0,1, 5,6,7>` is a translation by <5,6,7>.
  const double values[12] = {1, 0, 0, 0, 1, 0, 0, 0, 1, 5, 6, 7};
  const auto t = Transform::pov_matrix(values);
  ASSERT_TRUE(t.has_value());
  expect_near(t->point({1, 1, 1}), {6, 7, 8});
  // A shear: x' = x + y (the y row's first element).
  const double shear[12] = {1, 0, 0, 1, 1, 0, 0, 0, 1, 0, 0, 0};
  expect_near(Transform::pov_matrix(shear)->point({0, 1, 0}), {1, 1, 0});
}

TEST(TransformTest, AxisRotationMatchesEulerRotation) {
  const Transform a = Transform::rotate_axis_degrees({0, 1, 0}, 37);
  const Transform e = Transform::rotate_xyz_degrees({0, 37, 0});
  expect_near(a.vector({0.2, 0.4, 0.9}), e.vector({0.2, 0.4, 0.9}));
}

TEST(TransformTest, BoundsOfRotatedBoxContainCorners) {
  const Transform t = Transform::rotate_xyz_degrees({0, 45, 0});
  const Bounds3 b = t.bounds({{-1, -1, -1}, {1, 1, 1}});
  EXPECT_NEAR(b.hi.x, std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(b.hi.y, 1.0, 1e-12);
}
