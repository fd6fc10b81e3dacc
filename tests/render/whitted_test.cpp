// The Whitted integrator against analytic POV-Ray values: ambient*colour + diffuse*colour*N.L for a lit
// sphere; Fresnel reflection numbers from ../shared/reference-values.md section 3.
#include "snell/render/whitted.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "scene_builder.hpp"
#include "snell/accel/accelerator.hpp"
#include "snell/math/constants.hpp"
#include "snell/render/renderer.hpp"

namespace snell::render {
namespace {

using math::Color;
using math::Vec3;

TEST(WhittedTest, LitDiffuseSphereCentreIsAmbientPlusLambert) {
  const scene::Scene s = test::lit_sphere_scene();
  const auto accel = accel::make_accelerator("none", s);
  RenderOptions o;
  o.width = 11;
  o.height = 11;
  o.threads = 1;
  const RenderResult r = Renderer(s, *accel, o).render();
  // Hit (0,0,-1), N = (0,0,-1), L towards (0,5,-6): N.L = 5/sqrt(50) = 1/sqrt(2).
  const double k = 0.1 + 0.6 / std::sqrt(2.0);
  const Color c = r.image.at(5, 5);
  EXPECT_NEAR(c.r, 1.0 * k, 1e-6);
  EXPECT_NEAR(c.g, 0.5 * k, 1e-6);
  EXPECT_NEAR(c.b, 0.25 * k, 1e-6);
  EXPECT_EQ(r.rays.camera, 121u);
  EXPECT_GT(r.rays.shadow, 0u);
  // A corner pixel misses the sphere: the (default black) background.
  EXPECT_EQ(r.image.at(0, 0).r, 0.0f);
}

TEST(WhittedTest, ShadowedPointGetsOnlyAmbient) {
  scene::Scene s = test::lit_sphere_scene();
  // An opaque blocker between the light and the lit point.
  s.objects.push_back(
      test::object(std::make_shared<geometry::Sphere>(Vec3(0, 2.5, -3.5), 0.5), test::texture({Color(1)})));
  const auto accel = accel::make_accelerator("none", s);
  WhittedIntegrator w(s, *accel);
  TraceContext ctx;
  const Color c = w.trace_camera_ray({{0, 0, -5}, {0, 0, 1}}, ctx);
  EXPECT_NEAR(c.r, 0.1, 1e-9);
  EXPECT_NEAR(c.g, 0.05, 1e-9);
}

TEST(WhittedTest, ShadowlessLightGivesNoHighlights) {
  // POV-Ray 3.7 draws no phong or specular highlight from a shadowless light (its fill light; trace.cpp,
  // ComputeOneDiffuseLight): its render of a sphere with specular 0.8 and phong 0.5 lit only by one shows
  // diffuse light alone. The light straight behind the camera puts both highlights at the sphere's centre.
  scene::Scene s = test::lit_sphere_scene();
  material::Finish shiny;
  shiny.specular = 0.8;
  shiny.roughness = 0.01;
  shiny.phong = 0.5;
  s.objects[0] = test::object(std::make_shared<geometry::Sphere>(Vec3(0, 0, 0), 1.0),
                              test::texture({Color(1, 0.5, 0.25)}, shiny));
  s.lights[0] = test::point_light({0, 0, -6});
  const auto accel = accel::make_accelerator("none", s);
  WhittedIntegrator w(s, *accel);
  TraceContext ctx;
  const double lit = w.trace_camera_ray({{0, 0, -5}, {0, 0, 1}}, ctx).b;
  EXPECT_NEAR(lit, 0.25 * 0.7 + 0.8 + 0.5, 1e-6);  // ambient + diffuse, specular, phong
  s.lights[0].shadowless = true;
  const auto accel2 = accel::make_accelerator("none", s);
  WhittedIntegrator w2(s, *accel2);
  EXPECT_NEAR(w2.trace_camera_ray({{0, 0, -5}, {0, 0, 1}}, ctx).b, 0.25 * 0.7, 1e-6);
}

TEST(WhittedTest, FilteredShadowIsTintedByTransparentBlocker) {
  scene::Scene s = test::lit_sphere_scene();
  // rgbf <0.5,1,1,1> blocker: the shadow ray crosses it twice, each time multiplied by filter*rgb.
  s.objects.push_back(test::object(std::make_shared<geometry::Sphere>(Vec3(0, 2.5, -3.5), 0.5),
                                   test::texture({Color(0.5, 1, 1), 1.0, 0.0})));
  const auto accel = accel::make_accelerator("none", s);
  WhittedIntegrator w(s, *accel);
  TraceContext ctx;
  const Color c = w.trace_camera_ray({{0, 0, -5}, {0, 0, 1}}, ctx);
  const double lambert = 0.6 / std::sqrt(2.0);
  EXPECT_NEAR(c.r, 0.1 + lambert * 0.25, 1e-9);
  EXPECT_NEAR(c.g, 0.5 * (0.1 + lambert), 1e-9);
}

TEST(WhittedTest, MirrorShowsBackground) {
  scene::Scene s;
  material::Finish f;
  f.ambient = Color(0);
  f.diffuse = 0;
  f.reflection_min = f.reflection_max = Color(1);
  s.objects.push_back(
      test::object(std::make_shared<geometry::Sphere>(Vec3(0, 0, 0), 1.0), test::texture({Color(0)}, f)));
  s.background.rgb = Color(0.2, 0.4, 0.6);
  const auto accel = accel::make_accelerator("none", s);
  WhittedIntegrator w(s, *accel);
  TraceContext ctx;
  const Color c = w.trace_camera_ray({{0, 0, -5}, {0, 0, 1}}, ctx);
  EXPECT_NEAR(c.b, 0.6, 1e-12);
  EXPECT_EQ(ctx.counters.reflected, 1u);
}

TEST(WhittedTest, FresnelReflectionOffGlassAt60Degrees) {
  scene::Scene s;
  material::Finish f;
  f.ambient = Color(0);
  f.diffuse = 0;
  f.reflection_min = Color(0);
  f.reflection_max = Color(1);
  f.reflection_fresnel = true;
  s.objects.push_back(
      test::object(std::make_shared<geometry::Plane>(Vec3(0, 1, 0), 0.0), test::texture({Color(0)}, f), 1.5));
  s.background.rgb = Color(1);
  const auto accel = accel::make_accelerator("none", s);
  WhittedIntegrator w(s, *accel);
  TraceContext ctx;
  const double a = math::radians(60);
  const Color c = w.trace_camera_ray({{0, 1, 0}, {std::sin(a), -std::cos(a), 0}}, ctx);
  // Reflected part only (the opaque black pigment lets nothing through): R(60°, 1 -> 1.5) = 0.089187.
  EXPECT_NEAR(c.r, 0.089187, 1e-6);
}

TEST(WhittedTest, TransmitPassesBackgroundThroughClearObject) {
  scene::Scene s;
  material::Finish f;
  f.ambient = Color(0);
  f.diffuse = 0;
  // rgbf <1,0.5,0.5,1>: entering and leaving each multiply by the filter colour.
  s.objects.push_back(test::object(std::make_shared<geometry::Sphere>(Vec3(0, 0, 0), 1.0),
                                   test::texture({Color(1, 0.5, 0.5), 1.0, 0.0}, f)));
  s.background.rgb = Color(0.8);
  const auto accel = accel::make_accelerator("none", s);
  WhittedIntegrator w(s, *accel);
  TraceContext ctx;
  const Color c = w.trace_camera_ray({{0, 0, -5}, {0, 0, 1}}, ctx);
  EXPECT_NEAR(c.r, 0.8, 1e-9);
  EXPECT_NEAR(c.g, 0.8 * 0.25, 1e-9);
  EXPECT_EQ(ctx.counters.refracted, 2u);
}

TEST(WhittedTest, LayeredTextureShowsLowerLayerThroughTransmit) {
  // POV-Ray "Layered Textures": a half-transmitting red layer over opaque blue shows half of each, and the
  // stack is opaque (nothing behind the object shows). Ambient 1, diffuse 0: the colour is the pigment.
  scene::Scene s;
  material::Finish f;
  f.ambient = Color(1);
  f.diffuse = 0;
  auto top = test::texture({Color(1, 0, 0), 0.0, 0.5}, f);
  top->below = test::texture({Color(0, 0, 1)}, f);
  s.objects.push_back(test::object(std::make_shared<geometry::Sphere>(Vec3(0, 0, 0), 1.0), top));
  s.background.rgb = Color(0, 1, 0);
  const auto accel = accel::make_accelerator("none", s);
  WhittedIntegrator w(s, *accel);
  TraceContext ctx;
  const Color c = w.trace_camera_ray({{0, 0, -5}, {0, 0, 1}}, ctx);
  EXPECT_NEAR(c.r, 0.5, 1e-9);
  EXPECT_NEAR(c.g, 0, 1e-9);
  EXPECT_NEAR(c.b, 0.5, 1e-9);
  EXPECT_EQ(ctx.counters.refracted, 0u);
}

TEST(WhittedTest, MaxTraceLevelStopsRecursion) {
  // Glass half-space below y=0 seen at 45°: with max_trace_level 1 only the camera ray is traced.
  scene::Scene s;
  material::Finish f;
  f.ambient = Color(0);
  f.diffuse = 0;
  s.objects.push_back(test::object(std::make_shared<geometry::Plane>(Vec3(0, 1, 0), 0.0),
                                   test::texture({Color(1), 0.0, 1.0}, f), 1.5));
  s.background.rgb = Color(0.5);
  s.settings.max_trace_level = 1;
  const auto accel = accel::make_accelerator("none", s);
  WhittedIntegrator w(s, *accel);
  TraceContext ctx;
  const double h = std::sqrt(0.5);
  EXPECT_EQ(w.trace_camera_ray({{0, 1, 0}, {h, -h, 0}}, ctx).r, 0.0);
  s.settings.max_trace_level = 5;
  EXPECT_NEAR(w.trace_camera_ray({{0, 1, 0}, {h, -h, 0}}, ctx).r, 0.5, 1e-12);
}

}  // namespace
}  // namespace snell::render
