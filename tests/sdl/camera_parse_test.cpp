// Camera types and focal blur as POV-Ray 3.7 parses them (reference "Camera", "Types of Projection",
// "Focal Blur"; defaults from the reference: angle 90, spherical 360 x 180, confidence 0.9,
// variance 1/10000, focal distance = direction length unless focal_point is given).
#include <gtest/gtest.h>

#include <cmath>

#include "sdl_test_util.hpp"

namespace snell::sdl {
namespace {

using Kind = scene::CameraSpec::Kind;

TEST(SdlCameraTypes, KeywordsSelectTheProjection) {
  EXPECT_EQ(test::parse("camera { fisheye }").camera.kind, Kind::fisheye);
  EXPECT_EQ(test::parse("camera { ultra_wide_angle }").camera.kind, Kind::ultra_wide_angle);
  EXPECT_EQ(test::parse("camera { omnimax }").camera.kind, Kind::omnimax);
  EXPECT_EQ(test::parse("camera { panoramic }").camera.kind, Kind::panoramic);
  EXPECT_EQ(test::parse("camera { spherical }").camera.kind, Kind::spherical);
  EXPECT_EQ(test::parse("camera { cylinder 1 }").camera.kind, Kind::cylinder1);
  EXPECT_EQ(test::parse("camera { cylinder 2 }").camera.kind, Kind::cylinder2);
  EXPECT_EQ(test::parse("camera { cylinder 3 }").camera.kind, Kind::cylinder3);
  EXPECT_EQ(test::parse("camera { cylinder 4 }").camera.kind, Kind::cylinder4);
}

TEST(SdlCameraTypes, AngleIsKeptForNonPlanarCameras) {
  // POV-Ray's default angle is 90 for every type (fisheye too: rendered with POV-Ray 3.7, an unset
  // fisheye angle frames 45 degrees at the rim of its circle).
  EXPECT_DOUBLE_EQ(test::parse("camera { fisheye }").camera.angle, 90);
  const auto cam = test::parse("camera { fisheye angle 360 location <1, 4, 3> look_at <0, 1, 2> }").camera;
  EXPECT_DOUBLE_EQ(cam.angle, 360);
  // The angle does not rescale direction for these types (only perspective and orthographic do).
  EXPECT_NEAR(length(cam.direction), 1, 1e-12);
  EXPECT_DOUBLE_EQ(test::parse("camera { cylinder 3 angle 200 }").camera.angle, 200);
}

TEST(SdlCameraTypes, SphericalTakesTwoAngles) {
  const auto both = test::parse("camera { spherical angle 120, 40 }").camera;
  EXPECT_DOUBLE_EQ(both.h_angle, 120);
  EXPECT_DOUBLE_EQ(both.v_angle, 40);
  const auto no_comma = test::parse("camera { spherical angle 120 40 location 1 }").camera;
  EXPECT_DOUBLE_EQ(no_comma.v_angle, 40);
  const auto one = test::parse("camera { spherical angle 120 }").camera;
  EXPECT_DOUBLE_EQ(one.h_angle, 120);
  EXPECT_DOUBLE_EQ(one.v_angle, 60);
  const auto none = test::parse("camera { spherical }").camera;
  EXPECT_DOUBLE_EQ(none.h_angle, 360);
  EXPECT_DOUBLE_EQ(none.v_angle, 180);
}

TEST(SdlCameraTypes, BadValuesAreErrors) {
  EXPECT_NE(test::error_of("camera { cylinder 5 }").find("cylinder camera type must be 1, 2, 3 or 4"),
            std::string::npos);
  EXPECT_NE(test::error_of("camera { cylinder 1.5 }").find("must be 1, 2, 3 or 4"), std::string::npos);
  EXPECT_NE(test::error_of("camera { perspective angle 190 }").find("below 180"), std::string::npos);
  EXPECT_EQ(test::error_of("camera { fisheye angle 190 }"), "");
  EXPECT_NE(test::error_of("camera { fisheye angle -1 }").find("negative camera angle"), std::string::npos);
  EXPECT_NE(test::error_of("camera { blur_samples 0 }").find("must be positive"), std::string::npos);
  EXPECT_NE(test::error_of("camera { blur_samples 20, 5 }").find("minimum must not be larger"),
            std::string::npos);
}

TEST(SdlFocalBlur, SamplesApertureAndConfidence) {
  const auto cam =
      test::parse("camera { aperture 0.4 blur_samples 7, 30 confidence 0.95 variance 0.001 }").camera;
  EXPECT_DOUBLE_EQ(cam.aperture, 0.4);
  EXPECT_EQ(cam.blur_samples_min, 7);
  EXPECT_EQ(cam.blur_samples, 30);
  EXPECT_DOUBLE_EQ(cam.confidence, 0.95);
  EXPECT_DOUBLE_EQ(cam.variance, 0.001);
  EXPECT_TRUE(cam.focal_blur());
  EXPECT_EQ(test::parse("camera { blur_samples 7 30 aperture 1 }").camera.blur_samples, 30);
  const auto one = test::parse("camera { aperture 1 blur_samples 12 }").camera;
  EXPECT_EQ(one.blur_samples, 12);
  EXPECT_EQ(one.blur_samples_min, 0);
  EXPECT_FALSE(test::parse("camera { blur_samples 12 }").camera.focal_blur());  // no aperture
  // Out-of-range confidence or variance: POV-Ray warns and keeps its default.
  std::vector<std::string> messages;
  const auto bad = test::parse("camera { confidence 1.5 variance 2 }", &messages).camera;
  EXPECT_DOUBLE_EQ(bad.confidence, 0.9);
  EXPECT_DOUBLE_EQ(bad.variance, 1.0 / 10000.0);
  EXPECT_EQ(messages.size(), 2u);
}

TEST(SdlFocalBlur, FocalDistance) {
  // focal_point: its distance from location (after look_at, before transforms).
  const auto fp =
      test::parse(
          "camera { location <50, 10, 30> look_at <0, 10, 0> angle 35 aperture 10 blur_samples 120 "
          "focal_point <5, 10, 5> }")
          .camera;
  EXPECT_NEAR(fp.focal_distance, std::hypot(45.0, 25.0), 1e-12);
  // Without it: the direction length, e.g. as angle sets it.
  const auto by_angle = test::parse("camera { right x*4/3 angle 50 aperture 1 blur_samples 4 }").camera;
  EXPECT_NEAR(by_angle.focal_distance, 0.5 * (4.0 / 3.0) / std::tan(25 * M_PI / 180), 1e-12);
  const auto plain = test::parse("camera { aperture 1 blur_samples 4 }").camera;
  EXPECT_DOUBLE_EQ(plain.focal_distance, 1);
  // Transforms move the camera and its focal point together: the distance is unchanged.
  const auto moved =
      test::parse("camera { location <0, 0, -5> focal_point <0, 0, 3> rotate y*30 translate 7 }").camera;
  EXPECT_NEAR(moved.focal_distance, 8, 1e-12);
  EXPECT_NEAR(length(moved.focal_point - moved.location), 8, 1e-12);
}

}  // namespace
}  // namespace snell::sdl
