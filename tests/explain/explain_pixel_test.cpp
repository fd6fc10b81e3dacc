// The explained samples are the rendered ones: with jittered anti-aliasing, the mean of a supersampled
// pixel's samples 0..depth^2 is the renderer's pixel, bit for bit in float.
#include "snell/render/explain/explain_pixel.hpp"

#include <gtest/gtest.h>

#include "explain_scenes.hpp"

namespace snell::render::explain {
namespace {

TEST(ExplainPixelTest, SamplesAverageToTheRenderedPixelWithJitter) {
  const scene::Scene scene = test::parse(test::kGlassSphere);
  const auto accel = accel::make_accelerator("bvh", scene);
  RenderOptions o;
  o.width = 32;
  o.height = 24;
  o.antialias = true;
  o.aa_threshold = 0.05;
  o.aa_depth = 2;
  o.jitter = true;
  o.threads = 2;
  const RenderResult rendered = Renderer(scene, *accel, o).render();
  // The sphere's rim at the centre row is supersampled; a corner pixel of the sky is not.
  int checked = 0;
  for (int x = 0; x < o.width; ++x) {
    const int y = o.height / 2;
    const math::Color first = explain_pixel(scene, *accel, o, x, y, 0).colour;
    math::Color sum = first;
    for (int k = 1; k < samples_per_pixel(o); ++k) sum += explain_pixel(scene, *accel, o, x, y, k).colour;
    const math::Color pixel = rendered.image.at(x, y);
    const math::Color mean = sum / static_cast<double>(samples_per_pixel(o));
    // Either the renderer kept the first sample or it averaged all of them.
    const bool kept_first = static_cast<float>(first.r) == static_cast<float>(pixel.r) &&
                            static_cast<float>(first.g) == static_cast<float>(pixel.g);
    const bool averaged = static_cast<float>(mean.r) == static_cast<float>(pixel.r) &&
                          static_cast<float>(mean.g) == static_cast<float>(pixel.g) &&
                          static_cast<float>(mean.b) == static_cast<float>(pixel.b);
    EXPECT_TRUE(kept_first || averaged) << x;
    checked += averaged && !kept_first;
  }
  EXPECT_GT(checked, 0) << "no supersampled pixel on the row";
}

}  // namespace
}  // namespace snell::render::explain

namespace snell::render::explain {
namespace {

// The renderer tries the last opaque blocker of each light first (the shadow cache); `explain` traces
// without it. A blocker whose checker cells alternate opaque and fully transmitting, above a floor,
// makes the cached object miss, block and let light through from one pixel to the next: every pixel must
// still be the uncached colour.
TEST(ExplainPixelTest, ShadowCacheLeavesEveryPixelAsTheUncachedTrace) {
  const scene::Scene scene = test::parse(
      "camera { location <0, 4, -5> look_at 0 }\n"
      "light_source { <1, 8, -1> rgb 1 }\n"
      "light_source { <-3, 6, -2> rgb 0.5 }\n"
      "plane { y, 0 pigment { rgb 1 } }\n"
      "box { <-1.5, 1, -1.5>, <1.5, 1.2, 1.5> pigment { checker rgb 0.5, rgbt <1, 0, 0, 1> scale 0.3 } }\n"
      "sphere { <1.5, 2, 0>, 0.4 pigment { rgbf <0.2, 0.9, 0.2, 0.7> } }\n");
  const auto accel = accel::make_accelerator("embree", scene);
  RenderOptions o;
  o.width = 24;
  o.height = 18;
  o.threads = 1;
  const RenderResult rendered = Renderer(scene, *accel, o).render();
  for (int y = 0; y < o.height; ++y)
    for (int x = 0; x < o.width; ++x) {
      const math::Color explained = explain_pixel(scene, *accel, o, x, y, 0).colour;
      const math::Color pixel = rendered.image.at(x, y);
      ASSERT_EQ(static_cast<float>(explained.r), static_cast<float>(pixel.r)) << x << "," << y;
      ASSERT_EQ(static_cast<float>(explained.g), static_cast<float>(pixel.g)) << x << "," << y;
      ASSERT_EQ(static_cast<float>(explained.b), static_cast<float>(pixel.b)) << x << "," << y;
    }
}

}  // namespace
}  // namespace snell::render::explain
