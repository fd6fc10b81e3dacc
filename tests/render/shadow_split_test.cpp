// Shadow rays in scenes with both opaque and transparent surfaces (render/shadow_split.hpp): an opaque
// blocker anywhere on the way blacks out the light even with transparent ones before and after it, a
// transparent one alone still tints it, and the split is made only where both kinds exist.
#include "snell/render/shadow_split.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "scene_builder.hpp"
#include "snell/render/whitted.hpp"

namespace snell::render {
namespace {

using math::Color;
using math::Vec3;

/// A sphere of radius r the fraction `along` of the way from the lit point (0, 0, -1) to the light.
std::shared_ptr<scene::Object> blocker(double along, double r, const material::Rgbft& pigment) {
  const Vec3 from{0, 0, -1}, to{0, 5, -6};
  return test::object(std::make_shared<geometry::Sphere>(from + (to - from) * along, r),
                      test::texture(pigment));
}

Color centre_colour(const scene::Scene& s) {
  const auto accel = accel::make_accelerator("embree", s);
  WhittedIntegrator w(s, *accel);
  TraceContext ctx;
  return w.trace_camera_ray({{0, 0, -5}, {0, 0, 1}}, ctx);
}

TEST(ShadowSplitTest, OpaqueBlockerBetweenTransparentOnesBlacksOutTheLight) {
  scene::Scene s = test::lit_sphere_scene();
  s.objects.push_back(blocker(0.2, 0.2, {Color(0.5, 1, 1), 1.0, 0.0}));
  s.objects.push_back(blocker(0.5, 0.2, {Color(1)}));
  s.objects.push_back(blocker(0.8, 0.2, {Color(1, 1, 0.5), 0.0, 1.0}));
  const Color c = centre_colour(s);
  EXPECT_NEAR(c.r, 0.1, 1e-9);  // ambient only
  EXPECT_NEAR(c.g, 0.05, 1e-9);
}

TEST(ShadowSplitTest, TransparentBlockersAloneTintTheLight) {
  scene::Scene s = test::lit_sphere_scene();
  s.objects.push_back(blocker(0.3, 0.2, {Color(0.5, 1, 1), 1.0, 0.0}));  // filter: x rgb, twice
  s.objects.push_back(blocker(0.7, 0.2, {Color(1, 1, 1), 0.0, 0.5}));    // transmit 0.5, twice
  // An opaque object off the path: the split exists, and does not block.
  s.objects.push_back(
      test::object(std::make_shared<geometry::Sphere>(Vec3(5, 0, 0), 1.0), test::texture({Color(1)})));
  const Color c = centre_colour(s);
  const double lambert = 0.6 / std::sqrt(2.0);
  EXPECT_NEAR(c.r, 0.1 + lambert * 0.25 * 0.25, 1e-9);
  EXPECT_NEAR(c.g, 0.5 * (0.1 + lambert * 0.25), 1e-9);
}

TEST(ShadowSplitTest, MadeOnlyWhereBothKindsExist) {
  scene::Scene s = test::lit_sphere_scene();
  const auto opaque_only = accel::make_accelerator("embree", s);
  EXPECT_EQ(ShadowSplit::make(s, *opaque_only), nullptr);
  s.objects.push_back(blocker(0.5, 0.2, {Color(1), 1.0, 0.0}));
  const auto both = accel::make_accelerator("embree", s);
  const auto split = ShadowSplit::make(s, *both);
  ASSERT_NE(split, nullptr);
  EXPECT_NE(split->summary().find("1 opaque, 1 transparent"), std::string::npos) << split->summary();
  s.objects.erase(s.objects.begin());
  const auto transparent_only = accel::make_accelerator("embree", s);
  EXPECT_EQ(ShadowSplit::make(s, *transparent_only), nullptr);
}

}  // namespace
}  // namespace snell::render
