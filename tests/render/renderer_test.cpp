#include "snell/render/renderer.hpp"

#include <gtest/gtest.h>

#include "scene_builder.hpp"

namespace snell::render {
namespace {

using math::Color;
using math::Vec3;

RenderResult render_with(int threads, bool aa, bool jitter, bool area_light = false,
                         double aa_compare_exponent = 0.4) {
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
  o.aa_compare_exponent = aa_compare_exponent;
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
  // Each supersampled pixel costs depth^2 = 9 more camera rays, and the first pass also traces the row
  // above the image and the column to its left, as POV-Ray's render blocks compare with them; a tile reads
  // its border from its neighbours' first samples (first_sample_grid.hpp), so no sample is traced twice.
  const uint64_t border = 72 + 54;
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

namespace snell::render {
namespace {

// POV-Ray compares anti-aliasing neighbours after decoding the working gamma and encoding with
// Antialias_Gamma 2.5 (view.cpp): for a linear scene each channel becomes c^(1/2.5).
TEST(RendererTest, AntiAliasingGammaExponentIsWorkingGammaOverAntialiasGamma) {
  EXPECT_DOUBLE_EQ(aa_compare_exponent_for(1.0, 2.5), 0.4);
  EXPECT_DOUBLE_EQ(aa_compare_exponent_for(2.2, 2.5), 0.88);
  EXPECT_DOUBLE_EQ(aa_compare_exponent_for(1.8, 0.0), 1.8);  // no Antialias_Gamma: decoding only
}

TEST(RendererTest, AntiAliasingGammaWeighsDarkDifferencesMore) {
  const double t = 0.3;  // +A0.3
  // Greys 0.02 and 0.08: 0.18 apart linearly, 3 * (0.08^0.4 - 0.02^0.4) = 0.465 after the gamma.
  EXPECT_LT(color_distance(Color(0.02), Color(0.08)), t);
  EXPECT_NEAR(color_distance(aa_encoded(Color(0.02), 0.4), aa_encoded(Color(0.08), 0.4)), 0.4649, 1e-4);
  // Greys 0.5 and 0.62: 0.36 apart linearly, 3 * (0.62^0.4 - 0.5^0.4) = 0.2043 after it.
  EXPECT_GT(color_distance(Color(0.5), Color(0.62)), t);
  EXPECT_NEAR(color_distance(aa_encoded(Color(0.5), 0.4), aa_encoded(Color(0.62), 0.4)), 0.2043, 1e-4);
  EXPECT_EQ(aa_encoded(Color(-0.5, 0.25, 1.0), 0.5), Color(0.0, 0.5, 1.0));
}

TEST(RendererTest, AntiAliasingGammaChangesWhichPixelsAreSupersampled) {
  const RenderResult linear = render_with(2, true, false, false, 1.0);
  const RenderResult pov = render_with(2, true, false, false, 0.4);
  EXPECT_GT(linear.supersampled_pixels, 0u);
  EXPECT_GT(pov.supersampled_pixels, 0u);
  EXPECT_NE(linear.supersampled_pixels, pov.supersampled_pixels);
}

}  // namespace
}  // namespace snell::render
