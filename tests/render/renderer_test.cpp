#include "snell/render/renderer.hpp"

#include <gtest/gtest.h>

#include "scene_builder.hpp"

namespace snell::render {
namespace {

using math::Color;
using math::Vec3;

scene::Scene two_spheres() {
  scene::Scene s;
  material::Finish shiny;
  shiny.phong = 0.8;
  shiny.reflection_min = shiny.reflection_max = Color(0.3);
  s.objects.push_back(test::object(std::make_shared<geometry::Sphere>(Vec3(-0.6, 0, 0), 0.7),
                                   test::texture({Color(0.9, 0.2, 0.1)}, shiny)));
  s.objects.push_back(test::object(std::make_shared<geometry::Sphere>(Vec3(0.7, 0.2, 0.5), 0.6),
                                   test::texture({Color(0.2, 0.9, 0.4), 0.6, 0.1}), 1.4));
  s.objects.push_back(
      test::object(std::make_shared<geometry::Plane>(Vec3(0, 1, 0), -0.7), test::texture({Color(0.8)})));
  s.lights.push_back(test::point_light({3, 5, -4}));
  s.background.rgb = Color(0.1, 0.2, 0.4);
  s.camera.location = {0, 0.5, -4};
  s.camera.right = {4.0 / 3, 0, 0};
  return s;
}

RenderResult render_with(int threads, bool aa, bool jitter, bool area_light = false) {
  scene::Scene s = two_spheres();
  if (area_light) {
    // A jittered, adaptive area light: its random grid offsets must not depend on which thread traces.
    scene::Light& l = s.lights.front();
    l.area = l.jitter = true;
    l.axis1 = {2, 0, 0};
    l.axis2 = {0, 0, 2};
    l.size1 = l.size2 = 5;
    l.adaptive = 1;
  }
  const auto accel = accel::make_accelerator("none", s);
  RenderOptions o;
  o.width = 72;
  o.height = 54;
  o.threads = threads;
  o.antialias = aa;
  o.jitter = jitter;
  o.seed = 7;
  return Renderer(s, *accel, o).render();
}

TEST(RendererTest, ImageIsBitIdenticalForAnyThreadCount) {
  for (const auto& [aa, jitter] : {std::pair{false, false}, std::pair{true, false}, std::pair{true, true}}) {
    const RenderResult one = render_with(1, aa, jitter);
    const RenderResult two = render_with(2, aa, jitter);
    EXPECT_EQ(one.image.rgb, two.image.rgb) << "aa " << aa << " jitter " << jitter;
    EXPECT_EQ(one.rays.total(), two.rays.total());
  }
}

TEST(RendererTest, JitteredAreaLightImageIsBitIdenticalForAnyThreadCount) {
  for (const bool aa : {false, true}) {
    const RenderResult one = render_with(1, aa, true, true);
    const RenderResult two = render_with(2, aa, true, true);
    EXPECT_EQ(one.image.rgb, two.image.rgb) << "aa " << aa;
    EXPECT_EQ(one.rays.total(), two.rays.total());
    // And the soft shadow differs from the point light's hard one.
    EXPECT_NE(one.image.rgb, render_with(1, aa, true, false).image.rgb);
  }
}

TEST(RendererTest, AntiAliasingSupersamplesOnlyEdges) {
  const RenderResult plain = render_with(2, false, false);
  const RenderResult aa = render_with(2, true, true);
  EXPECT_GT(aa.supersampled_pixels, 0u);
  EXPECT_LT(aa.supersampled_pixels, 72u * 54u / 2);
  // Each supersampled pixel costs depth^2 = 9 more camera rays.
  EXPECT_EQ(aa.rays.camera, plain.rays.camera + 9 * aa.supersampled_pixels);
  EXPECT_NE(plain.image.rgb, aa.image.rgb);
}

TEST(RendererTest, ColorDistanceIsSumOfChannelDifferences) {
  EXPECT_DOUBLE_EQ(color_distance(Color(0.1, 0.2, 0.3), Color(0.2, 0.0, 0.3)), 0.3);
}

TEST(RendererTest, RejectsBadSizes) {
  const scene::Scene s = two_spheres();
  const auto accel = accel::make_accelerator("none", s);
  RenderOptions o;
  o.width = 0;
  EXPECT_THROW(Renderer(s, *accel, o), std::invalid_argument);
  o.width = 10;
  o.aa_depth = 0;
  EXPECT_THROW(Renderer(s, *accel, o), std::invalid_argument);
}

}  // namespace
}  // namespace snell::render
