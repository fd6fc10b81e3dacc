// Primary ray directions of each POV-Ray 3.7 camera type at the image centre and edges, worked out by hand
// from the projections the POV-Ray reference describes ("Types of Projection"): e.g. a 180 degree fisheye
// sees straight sideways at the rim of its circle, a 360 degree spherical camera looks backwards at the
// left and right edges.
#include "snell/scene/camera.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "snell/math/constants.hpp"

namespace snell::scene {
namespace {

using math::Vec3;
using Kind = CameraSpec::Kind;

void expect_vec(const Vec3& got, const Vec3& want, double tol = 1e-9) {
  EXPECT_NEAR(got.x, want.x, tol);
  EXPECT_NEAR(got.y, want.y, tol);
  EXPECT_NEAR(got.z, want.z, tol);
}

CameraSpec square(Kind kind, double angle) {
  CameraSpec s;
  s.kind = kind;
  s.angle = angle;
  s.right = {1, 0, 0};
  return s;
}

Vec3 dir(const CameraSpec& s, double sx, double sy) {
  const auto ray = make_camera(s)->generate_ray(sx, sy, 0);
  EXPECT_TRUE(ray.has_value()) << "no ray at " << sx << ", " << sy;
  return ray ? ray->direction : Vec3(0);
}

const double kR = std::sqrt(0.5);

TEST(Camera, PerspectiveThroughImagePlane) {
  CameraSpec s;  // right 1.33, up 1, direction z
  expect_vec(dir(s, 0.5, 0.5), {0, 0, 1});
  expect_vec(dir(s, 1, 0), normalize(Vec3(0.665, 0.5, 1)));
}

TEST(Camera, FisheyeAngleSpansTheImageCircle) {
  const CameraSpec s = square(Kind::fisheye, 180);
  expect_vec(dir(s, 0.5, 0.5), {0, 0, 1});
  expect_vec(dir(s, 1, 0.5), {1, 0, 0});       // rim: 90 degrees off axis
  expect_vec(dir(s, 0.5, 0), {0, 1, 0});       // top
  expect_vec(dir(s, 0, 0.5), {-1, 0, 0});      // left
  expect_vec(dir(s, 0.75, 0.5), {kR, 0, kR});  // half way out: 45 degrees
  // Corners lie outside the circle: POV-Ray traces no ray there.
  EXPECT_FALSE(make_camera(s)->generate_ray(0.02, 0.02, 0).has_value());
  // 360 degrees: half way out already looks sideways.
  expect_vec(dir(square(Kind::fisheye, 360), 0.75, 0.5), {1, 0, 0});
}

TEST(Camera, FisheyeCircleFollowsRightLength) {
  CameraSpec s = square(Kind::fisheye, 180);
  s.right = {4.0 / 3.0, 0, 0};  // wide image: the circle fits the height
  EXPECT_FALSE(make_camera(s)->generate_ray(1, 0.5, 0).has_value());
  expect_vec(dir(s, 0.5 + 0.375, 0.5), {1, 0, 0});
}

TEST(Camera, UltraWideAngleIsLinearInAngle) {
  const CameraSpec s = square(Kind::ultra_wide_angle, 180);
  expect_vec(dir(s, 0.5, 0.5), {0, 0, 1});
  expect_vec(dir(s, 1, 0.5), {1, 0, 0});
  expect_vec(dir(s, 0.5, 0), {0, 1, 0});
  expect_vec(dir(s, 0.75, 0.5), {kR, 0, kR});
}

TEST(Camera, PanoramicCoversHalfACircleAcross) {
  const CameraSpec s = square(Kind::panoramic, 0);
  expect_vec(dir(s, 0.5, 0.5), {0, 0, 1});
  expect_vec(dir(s, 1, 0.5), {1, 0, 0});
  expect_vec(dir(s, 0, 0.5), {-1, 0, 0});
  expect_vec(dir(s, 0.5, 0.25), {0, kR, kR});  // latitude 45 degrees
}

TEST(Camera, CylinderOneAndTwoBendOneAxis) {
  const CameraSpec c1 = square(Kind::cylinder1, 90);
  expect_vec(dir(c1, 1, 0.5), {kR, 0, kR});
  expect_vec(dir(c1, 0.5, 0), normalize(Vec3(0, 0.5, 1)));  // up stays planar
  const CameraSpec c2 = square(Kind::cylinder2, 90);
  expect_vec(dir(c2, 0.5, 0), {0, kR, kR});
  expect_vec(dir(c2, 1, 0.5), normalize(Vec3(0.5, 0, 1)));
}

TEST(Camera, CylinderThreeAndFourMoveTheViewpoint) {
  CameraSpec c3 = square(Kind::cylinder3, 90);
  c3.location = {1, 2, 3};
  c3.up = {0, 2, 0};  // the viewpoint moves by up's length over the image
  const auto top = make_camera(c3)->generate_ray(0.5, 0, 0);
  ASSERT_TRUE(top);
  expect_vec(top->origin, {1, 3, 3});
  expect_vec(top->direction, {0, 0, 1});
  expect_vec(dir(c3, 1, 0.5), {kR, 0, kR});
  CameraSpec c4 = square(Kind::cylinder4, 90);
  const auto right = make_camera(c4)->generate_ray(1, 0.5, 0);
  ASSERT_TRUE(right);
  expect_vec(right->origin, {0.5, 0, 0});
  expect_vec(right->direction, {0, 0, 1});
  expect_vec(dir(c4, 0.5, 0), {0, kR, kR});
}

TEST(Camera, SphericalMapsLongitudeAndLatitude) {
  CameraSpec s = square(Kind::spherical, 0);
  s.h_angle = 360;
  s.v_angle = 180;
  expect_vec(dir(s, 0.5, 0.5), {0, 0, 1});
  expect_vec(dir(s, 0.75, 0.5), {1, 0, 0});
  expect_vec(dir(s, 0.25, 0.5), {-1, 0, 0});
  expect_vec(dir(s, 1, 0.5), {0, 0, -1}, 1e-9);
  expect_vec(dir(s, 0.5, 0), {0, 1, 0});
  expect_vec(dir(s, 0.75, 0.25), {kR, kR, 0});  // latitude 45, longitude 90
}

TEST(Camera, OmnimaxUsesItsLensPolynomial) {
  // Square image: the centre looks ahead; out at radius r the polar angle is POV-Ray's polynomial.
  const CameraSpec sq = square(Kind::omnimax, 0);
  expect_vec(dir(sq, 0.5, 0.5), {0, 0, 1});
  const auto poly = [](double r) { return 1.411269 * r - 0.09439 * r * r * r + 0.25674 * std::pow(r, 5); };
  expect_vec(dir(sq, 0.95, 0.5), {std::sin(poly(0.9)), 0, std::cos(poly(0.9))});
  expect_vec(dir(sq, 0.5, 0.05), {0, std::sin(poly(0.9)), std::cos(poly(0.9))});
  // At the rim the polynomial passes 90 degrees; the dome sees nothing behind its horizon there.
  EXPECT_GT(poly(1), math::kPi / 2);
  EXPECT_FALSE(make_camera(sq)->generate_ray(1, 0.5, 0).has_value());
  EXPECT_FALSE(make_camera(sq)->generate_ray(0.5, 1, 0).has_value());
  // 4:3 image: the dome's centre sits below the image centre (OMNIMAX frames the horizon low), so the
  // image centre looks above the axis, by the polynomial at radius 1 - 1/1.283458.
  CameraSpec wide = sq;
  wide.right = {4.0 / 3.0, 0, 0};
  const double theta = poly(1 - 1 / 1.283458);
  expect_vec(dir(wide, 0.5, 0.5), {0, std::sin(theta), std::cos(theta)});
}

TEST(Camera, FollowsTransformedBasis) {
  // Looking down -x with up z: the fisheye's rim to the right is right's direction.
  CameraSpec s = square(Kind::fisheye, 180);
  s.direction = {-1, 0, 0};
  s.up = {0, 0, 1};
  s.right = {0, 1, 0};
  expect_vec(dir(s, 0.5, 0.5), {-1, 0, 0});
  expect_vec(dir(s, 1, 0.5), {0, 1, 0});
  expect_vec(dir(s, 0.5, 0), {0, 0, 1});
}

// Focal blur: every lens ray through one image point passes through the pinhole ray's point on the focal
// plane, and rays from different lens points spread apart off that plane.
TEST(Camera, FocalPlaneStaysSharp) {
  CameraSpec s;
  s.location = {1, 2, 3};
  s.direction = {0, 0, 2};
  s.aperture = 3;
  s.blur_samples = 10;
  s.focal_distance = 7;
  const auto cam = make_camera(s);
  for (const auto& [sx, sy] : {std::pair{0.5, 0.5}, std::pair{0.1, 0.8}, std::pair{0.9, 0.2}}) {
    const auto pin = cam->generate_ray(sx, sy, 0);
    ASSERT_TRUE(pin);
    const double t = 7 / pin->direction.z;  // focal plane z = 3 + 7
    const Vec3 focus = pin->at(t);
    double spread = 0;
    for (const auto& [u, v] : {std::pair{0.5, 0.0}, std::pair{-0.3, 0.35}, std::pair{0.0, -0.5}}) {
      const auto lens = cam->generate_lens_ray(sx, sy, u, v, 0);
      ASSERT_TRUE(lens);
      EXPECT_NEAR(length(lens->direction), 1, 1e-12);
      // The lens point is aperture/2 * (u, v) across the lens, in the plane perpendicular to direction.
      EXPECT_NEAR(length(lens->origin - s.location), 1.5 * std::hypot(u, v), 1e-12);
      EXPECT_NEAR(lens->origin.z, 3, 1e-12);
      const double tl = (10 - lens->origin.z) / lens->direction.z;
      expect_vec(lens->at(tl), focus, 1e-9);
      const double near_t = (5 - lens->origin.z) / lens->direction.z;
      spread = std::max(spread, length(lens->at(near_t) - pin->at((5 - 3) / pin->direction.z)));
    }
    EXPECT_GT(spread, 0.5);  // off the focal plane the rays do not meet
  }
}

}  // namespace
}  // namespace snell::scene
