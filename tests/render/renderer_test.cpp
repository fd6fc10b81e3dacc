#include "snell/render/renderer.hpp"

#include <gtest/gtest.h>

#include "scene_builder.hpp"

namespace snell::render {
namespace {

using math::Color;
using math::Vec3;

RenderResult render_with(int threads, bool aa, bool jitter, bool area_light = false) {
  scene::Scene s = test::two_spheres();
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
  // Each supersampled pixel costs depth^2 = 9 more camera rays, and each tile re-traces the first-pass
  // samples of its one-pixel border (tiles are self-contained).
  uint64_t border = 0;
  for (const Tile& t : make_tiles(72, 54, {0, 0, 72, 54})) {
    const PixelRect& r = t.rect;
    const PixelRect b{std::max(r.x0 - 1, 0), std::max(r.y0 - 1, 0), std::min(r.x1 + 1, 72),
                      std::min(r.y1 + 1, 54)};
    border += static_cast<uint64_t>(b.area() - r.area());
  }
  EXPECT_EQ(aa.rays.camera, plain.rays.camera + 9 * aa.supersampled_pixels + border);
  EXPECT_NE(plain.image.rgb, aa.image.rgb);
}

TEST(RendererTest, ColorDistanceIsSumOfChannelDifferences) {
  EXPECT_DOUBLE_EQ(color_distance(Color(0.1, 0.2, 0.3), Color(0.2, 0.0, 0.3)), 0.3);
}

TEST(RendererTest, RejectsBadSizes) {
  const scene::Scene s = test::two_spheres();
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
