#include <gtest/gtest.h>

#include <cmath>

#include "sdl_test_util.hpp"
#include "snell/geometry/blob.hpp"
#include "snell/geometry/sphere.hpp"

namespace snell::sdl {
namespace {

void expect_near(const math::Vec3& a, const math::Vec3& b, double tol = 1e-12) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

TEST(SdlCamera, DefaultsArePovRays) {
  const auto cam = test::parse("camera { }").camera;
  expect_near(cam.location, {0, 0, 0});
  expect_near(cam.direction, {0, 0, 1});
  expect_near(cam.up, {0, 1, 0});
  expect_near(cam.right, {1.33, 0, 0});
}

TEST(SdlCamera, LookAtReaimsKeepingLengths) {
  // POV-Ray: direction = |direction| * unit(look_at - location); right = |right| * unit(sky x direction);
  // up = |up| * (direction x right).
  const auto cam =
      test::parse("camera { location <0, 0, -5> direction 2*z right x*2 up y*3 look_at <5, 0, -5> }").camera;
  expect_near(cam.direction, {2, 0, 0});
  expect_near(cam.right, {0, 0, -2});
  expect_near(cam.up, {0, 3, 0});
}

TEST(SdlCamera, OrderOfModifiersDoesNotMatter) {
  const auto a = test::parse("camera { look_at <1, 2, 3> location <0, 1, -4> right x*4/3 angle 60 }").camera;
  const auto b = test::parse("camera { angle 60 right x*4/3 location <0, 1, -4> look_at <1, 2, 3> }").camera;
  expect_near(a.direction, b.direction);
  expect_near(a.right, b.right);
  expect_near(a.up, b.up);
}

TEST(SdlCamera, AngleSetsDirectionLengthFromRight) {
  // Reference "angle": direction length = 0.5 * |right| / tan(angle / 2).
  const auto cam = test::parse("camera { right x*4/3 angle 50 }").camera;
  EXPECT_NEAR(length(cam.direction), 0.5 * (4.0 / 3.0) / std::tan(25 * M_PI / 180), 1e-12);
  expect_near(normalize(cam.direction), {0, 0, 1});
}

TEST(SdlCamera, RightHandedCameraStaysRightHanded) {
  const auto cam = test::parse("camera { right -x*4/3 location <0, 0, -5> look_at <0, 0, 0> }").camera;
  expect_near(cam.right, {-4.0 / 3.0, 0, 0});
}

TEST(SdlCamera, TransformsApplyLast) {
  const auto cam = test::parse("camera { location <0, 0, -5> look_at 0 rotate y*90 translate x }").camera;
  expect_near(cam.location, {-4, 0, 0});
  expect_near(cam.direction, {1, 0, 0});
}

TEST(SdlCamera, OrthographicWithExplicitUpAndRightKeepsThem) {
  const auto cam =
      test::parse("camera { orthographic location <0, 6, -6> look_at 0 right x*8 up y*6 }").camera;
  EXPECT_EQ(cam.kind, scene::CameraSpec::Kind::orthographic);
  EXPECT_NEAR(length(cam.right), 8, 1e-12);
  EXPECT_NEAR(length(cam.up), 6, 1e-12);
}

TEST(SdlLights, PointSpotAndAreaFields) {
  const auto scene = test::parse(R"(
    light_source { <0, 6, 0> color rgb 1.5 spotlight point_at <1, 0, 1> radius 15 falloff 25 tightness 5 }
    light_source { <-3, 2, -3> color rgb <0.4, 0.2, 0.1> fade_distance 2 fade_power 2 shadowless }
    light_source { 0, 1 area_light x, z, 4, 3 adaptive 1 jitter circular orient translate <1, 2, 3> }
    light_source { <0, 10, 0>, rgb 1 parallel point_at 0 }
  )");
  ASSERT_EQ(scene.lights.size(), 4u);
  const auto& spot = scene.lights[0];
  EXPECT_EQ(spot.kind, scene::Light::Kind::spotlight);
  EXPECT_EQ(spot.color, math::Color(1.5));
  expect_near(spot.point_at, {1, 0, 1});
  EXPECT_EQ(spot.radius, 15);
  EXPECT_EQ(spot.falloff, 25);
  EXPECT_EQ(spot.tightness, 5);
  EXPECT_EQ(scene.lights[1].fade_distance, 2);
  EXPECT_EQ(scene.lights[1].fade_power, 2);
  EXPECT_TRUE(scene.lights[1].shadowless);
  const auto& area = scene.lights[2];
  EXPECT_TRUE(area.area && area.jitter && area.circular && area.orient);
  EXPECT_EQ(area.size1, 4);
  EXPECT_EQ(area.size2, 3);
  expect_near(area.position, {1, 2, 3});
  EXPECT_EQ(scene.lights[3].kind, scene::Light::Kind::parallel);
}

TEST(SdlFinish, EveryField) {
  const auto scene = test::parse(R"(
    sphere { 0, 1 finish { ambient 0.2 emission rgb <0.1, 0.2, 0.3> diffuse 0.7 brilliance 2 crand 0.1
      phong 0.9 phong_size 60 specular 0.4 roughness 0.02 metallic
      reflection { 0.1, 0.8 fresnel on falloff 2 exponent 0.5 metallic 0.3 } conserve_energy } }
    sphere { 0, 1 finish { reflection 0.85 metallic 0.5 } }
  )");
  const auto& f = scene.objects[0]->texture->finish;
  EXPECT_EQ(f.ambient, math::Color(0.2));
  EXPECT_TRUE(f.ambient_set);
  EXPECT_EQ(f.emission, math::Color(0.1, 0.2, 0.3));
  EXPECT_EQ(f.diffuse, 0.7);
  EXPECT_EQ(f.brilliance, 2);
  EXPECT_EQ(f.crand, 0.1);
  EXPECT_EQ(f.phong, 0.9);
  EXPECT_EQ(f.phong_size, 60);
  EXPECT_EQ(f.specular, 0.4);
  EXPECT_EQ(f.roughness, 0.02);
  EXPECT_EQ(f.metallic, 1);
  EXPECT_EQ(f.reflection_min, math::Color(0.1));
  EXPECT_EQ(f.reflection_max, math::Color(0.8));
  EXPECT_TRUE(f.reflection_fresnel);
  EXPECT_EQ(f.reflection_falloff, 2);
  // POV-Ray keeps 1 / exponent and raises the reflection to that (parstxtr.cpp): its render of a mirror
  // with reflection { 1 exponent 0.5 } before a background of 0.25 reads 0.0625 (HDR).
  EXPECT_EQ(f.reflection_exponent, 2.0);
  EXPECT_EQ(f.reflection_metallic, 0.3);
  EXPECT_TRUE(f.conserve_energy);
  const auto& g = scene.objects[1]->texture->finish;
  EXPECT_EQ(g.reflection_min, math::Color(0.85));
  EXPECT_EQ(g.reflection_max, math::Color(0.85));
  EXPECT_EQ(g.metallic, 0.5);
  // The pigment stays POV-Ray's default (black) when only a finish is given.
  EXPECT_EQ(test::solid_color(*scene.objects[1]).rgb, math::Color(0));
}

TEST(SdlInterior, Fields) {
  const auto scene = test::parse(
      "#declare I = interior { ior 1.5 caustics 0.5 dispersion 1.1 fade_distance 2 fade_power 1001 "
      "fade_color rgb <1, 0, 0> }\n"
      "sphere { 0, 1 interior { I } }");
  const auto& i = *scene.objects[0]->interior;
  EXPECT_EQ(i.ior, 1.5);
  EXPECT_EQ(i.caustics, 0.5);
  EXPECT_EQ(i.dispersion, 1.1);
  EXPECT_EQ(i.fade_distance, 2);
  EXPECT_EQ(i.fade_power, 1001);
  EXPECT_EQ(i.fade_color, math::Color(1, 0, 0));
}

TEST(SdlObjects, TransformsComposeInOrderAndMoveTheTexture) {
  const auto scene =
      test::parse("sphere { 0, 1 scale 2 pigment { rgb 1 } translate <1, 0, 0> rotate <0, 0, 90> }");
  const auto& o = *scene.objects[0];
  // scale, then translate x, then rotate 90 about z: (1,0,0) -> (2,0,0) -> (3,0,0) -> (0,3,0).
  expect_near(o.transform.point({1, 0, 0}), {0, 3, 0});
  // The texture was attached after the scale: it moves with the translate and rotate only.
  expect_near(o.texture->transform.point({0, 0, 0}), {0, 1, 0});
  expect_near(o.texture->transform.point({1, 0, 0}), {0, 2, 0});
}

TEST(SdlObjects, ZeroScaleComponentIsIgnoredWithAWarning) {
  std::vector<std::string> messages;
  const auto scene = test::parse("sphere { 0, 1 scale <2, 0, 1> }", &messages);
  expect_near(scene.objects[0]->transform.point({1, 1, 1}), {2, 1, 1});
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_NE(messages[0].find("warning: scale component is zero"), std::string::npos);
}

TEST(SdlObjects, MatrixAndNamedTransform) {
  const auto scene = test::parse(R"(
    #declare T = transform { scale 2 translate y }
    sphere { 0, 1 matrix <1, 0, 0, 0, 1, 0, 0, 0, 1, 5, 6, 7> }
    sphere { 0, 1 transform T }
    sphere { 0, 1 transform { T inverse } }
  )");
  // Where each unit sphere ends up (its world box: the placement may be baked into the sphere itself).
  const auto placed = [&](size_t i, const math::Vec3& centre, double radius) {
    const math::Bounds3 b = scene.objects[i]->world_bounds();
    expect_near(b.center(), centre);
    expect_near(b.extent(), math::Vec3(2 * radius));
  };
  placed(0, {5, 6, 7}, 1);
  placed(1, {0, 1, 0}, 2);
  placed(2, {0, -0.5, 0}, 0.5);
}

TEST(SdlObjects, UnionFlattensWithComposedTransformsAndInheritedMaterial) {
  const auto scene = test::parse(R"(
    #declare U = union {
      sphere { <1, 0, 0>, 0.5 }
      sphere { <0, 1, 0>, 0.5 pigment { rgb <0, 1, 0> } translate x }
      union { sphere { 0, 0.25 } no_shadow }
      pigment { rgb <1, 0, 0> }
      interior { ior 1.3 }
      translate <0, 0, 10>
    }
    object { U scale 2 }
  )");
  ASSERT_EQ(scene.objects.size(), 3u);
  const auto& a = *scene.objects[0];
  const auto& b = *scene.objects[1];
  const auto& c = *scene.objects[2];
  expect_near(a.world_bounds().center(), {2, 0, 20});  // (1, 0, 0) moved by translate 10z, scale 2
  EXPECT_EQ(test::solid_color(a).rgb, math::Color(1, 0, 0));
  EXPECT_EQ(test::solid_color(b).rgb, math::Color(0, 1, 0));
  EXPECT_EQ(test::solid_color(c).rgb, math::Color(1, 0, 0));
  expect_near(b.world_bounds().center(), {2, 2, 20});  // (0, 1, 0) + x, then as a
  // b's own texture was attached before its translate: it moves with translate, union translate, scale.
  expect_near(b.texture->transform.point({0, 0, 0}), {2, 0, 20});
  ASSERT_TRUE(a.interior && c.interior);
  EXPECT_EQ(a.interior->ior, 1.3);
  EXPECT_TRUE(c.flags.no_shadow);
  EXPECT_FALSE(a.flags.no_shadow);
  EXPECT_EQ(a.name, "U");
}

TEST(SdlObjects, FlagsAndDeclaredTextures) {
  const auto scene = test::parse(R"(
    #declare Tex = texture { pigment { rgbf <0.96, 0.98, 1.0, 0.92> } finish { ambient 0 specular 0.9 } }
    sphere { 0, 1 texture { Tex } no_shadow no_image no_reflection hollow double_illuminate inverse }
    plane { y, -1 }
  )");
  ASSERT_EQ(scene.objects.size(), 2u);
  const auto& f = scene.objects[0]->flags;
  EXPECT_TRUE(f.no_shadow && f.no_image && f.no_reflection && f.hollow && f.double_illuminate && f.inverse);
  EXPECT_EQ(test::solid_color(*scene.objects[0]), (material::Rgbft{{0.96, 0.98, 1.0}, 0.92, 0}));
  EXPECT_EQ(scene.objects[0]->texture->finish.specular, 0.9);
  EXPECT_EQ(scene.objects[1]->texture, material::Texture::default_texture());
}

TEST(SdlObjects, BlobComponentsInBothSyntaxes) {
  const auto scene = test::parse(R"(
    blob { threshold 0.5
      sphere { <-0.8, 0.3, 0>, 1.1, 1 }
      cylinder { <-1.2, -0.4, 0>, <1.2, -0.4, 0>, 0.5, strength -1 }
      component 1.0, 1.0, <0.75, 0, 0>
    }
  )");
  ASSERT_EQ(scene.objects.size(), 1u);
  const auto* blob = dynamic_cast<const geometry::Blob*>(scene.objects[0]->shape.get());
  ASSERT_NE(blob, nullptr);
  // At the old-syntax component's centre: its own full strength 1, plus the sphere's tail
  // 1 * (1 - (r/R)^2)^2 with r^2 = 1.55^2 + 0.3^2 > R^2 = 1.21 -> 0, and the negative cylinder at
  // distance sqrt(0.4^2) = 0.4 < 0.5: -1 * (1 - 0.64)^2 = -0.1296.
  EXPECT_NEAR(blob->density({0.75, 0, 0}), 1 - 0.1296, 1e-12);
}

TEST(SdlScene, BackgroundGlobalSettingsAndVersion) {
  std::vector<std::string> messages;
  const auto scene = test::parse(R"(
    #version 3.6;
    global_settings { assumed_gamma 1.0 max_trace_level 8 adc_bailout 0.01 ambient_light rgb <1, 0.5, 0>
      radiosity { count 100 } }
    global_settings { assumed_gamma 2.2 }
    background { color rgb <0.1, 0.2, 0.3> }
  )",
                                 &messages);
  EXPECT_EQ(scene.settings.assumed_gamma, 1.0);
  EXPECT_EQ(scene.settings.max_trace_level, 8);
  EXPECT_EQ(scene.settings.adc_bailout, 0.01);
  EXPECT_EQ(scene.settings.ambient_light, math::Color(1, 0.5, 0));
  EXPECT_EQ(scene.settings.language_version, 3.6);
  EXPECT_EQ(scene.background.rgb, math::Color(0.1, 0.2, 0.3));
  ASSERT_TRUE(scene.settings.radiosity);  // read now, no longer skipped with a warning
  EXPECT_EQ(scene.settings.radiosity->count, 100);
  EXPECT_EQ(messages.size(), 1u);  // second assumed_gamma ignored
}

TEST(SdlScene, BlobExampleFromPovRay) {
  ParseOptions options;
  options.message_sink = [](const std::string&) {};
  const auto scene = parse_scene_file("/usr/share/doc/povray/examples/objects/blob.pov", options);
  ASSERT_EQ(scene.objects.size(), 1u);
  EXPECT_EQ(scene.objects[0]->shape->kind(), "blob");
  ASSERT_EQ(scene.lights.size(), 2u);
  expect_near(scene.lights[0].position, {-15, 30, -25});
  expect_near(scene.lights[1].position, {15, 30, -25});
  EXPECT_EQ(scene.lights[0].color, math::Color(1));
  expect_near(scene.camera.location, {0, 0, -5});
  expect_near(scene.camera.direction, {0, 0, 1.7});
  expect_near(scene.camera.right, {320.0 / 240.0, 0, 0});
  expect_near(scene.camera.up, {0, 1, 0});
  EXPECT_EQ(scene.background.rgb, math::Color(0.02));
  EXPECT_EQ(scene.settings.assumed_gamma, 1.0);
  const auto& o = *scene.objects[0];
  EXPECT_EQ(test::solid_color(o).rgb, math::Color(0.7, 0, 0.05));
  EXPECT_EQ(o.texture->finish.diffuse, 0.7);
  EXPECT_EQ(o.texture->finish.phong, 1);
  // rotate 30*y: (1,0,0) -> (cos 30, 0, -sin 30) in POV-Ray's left-handed rotation.
  expect_near(o.transform.point({1, 0, 0}), {std::cos(M_PI / 6), 0, -std::sin(M_PI / 6)});
}

TEST(SdlScene, RegressionAndShowcaseScenesParse) {
  const std::string root = SNELL_SOURCE_DIR;
  const std::pair<const char*, size_t> scenes[] = {{"tests/images/scenes/blob_metaballs.pov", 1},
                                                   {"tests/images/scenes/filtered_shadows.pov", 4},
                                                   {"tests/images/scenes/lights_and_camera.pov", 4},
                                                   {"tests/images/scenes/lit_spheres.pov", 4},
                                                   {"tests/images/scenes/mirror_and_glass.pov", 4},
                                                   {"tests/images/scenes/shapes.pov", 10},
                                                   {"scenes/showcase.pov", 13}};
  for (const auto& [file, objects] : scenes) {
    SCOPED_TRACE(file);
    std::vector<std::string> messages;
    ParseOptions options;
    options.message_sink = [&](const std::string& m) { messages.push_back(m); };
    const auto scene = parse_scene_file(root + "/" + file, options);
    EXPECT_EQ(scene.objects.size(), objects);
    EXPECT_TRUE(messages.empty()) << messages.front();
  }
}

}  // namespace
}  // namespace snell::sdl
