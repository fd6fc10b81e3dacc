// bounded_by as the parser stores it: the box of the bounding objects, in world space, on the bounded
// object, or on every object of a bounded union (POV-Ray 3.7 reference, "Bounded_By").
#include <gtest/gtest.h>

#include "sdl_test_util.hpp"

namespace snell::sdl {
namespace {

void expect_box(const scene::Object& o, const math::Vec3& lo, const math::Vec3& hi) {
  ASSERT_TRUE(o.bounded_by.has_value());
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(o.bounded_by->lo[a], lo[a], 1e-12);
    EXPECT_NEAR(o.bounded_by->hi[a], hi[a], 1e-12);
  }
}

TEST(SdlBoundedBy, BoxOfTheBoundMovesWithTheObject) {
  const scene::Scene s = test::parse(R"(
    sphere { 0, 2 bounded_by { box { -1, 1 } } translate <0, 0, 5> }
    sphere { 0, 1 }
  )");
  ASSERT_EQ(s.objects.size(), 2u);
  expect_box(*s.objects[0], {-1, -1, 4}, {1, 1, 6});
  EXPECT_FALSE(s.objects[1]->bounded_by.has_value());
}

TEST(SdlBoundedBy, SeveralBoundsIntersectAndUnionsPassTheirBoundOn) {
  // Two bounding boxes: a ray must hit both, so the culling box is their overlap, x in [0, 1].
  const scene::Scene s = test::parse(R"(
    union {
      sphere { 0, 1 }
      sphere { x, 1 }
      bounded_by { box { <-1, -1, -1>, <1, 1, 1> } box { <0, -2, -2>, <2, 2, 2> } }
    }
  )");
  ASSERT_EQ(s.objects.size(), 2u);  // the plain union is still flattened
  for (const auto& o : s.objects) expect_box(*o, {0, -1, -1}, {1, 1, 1});
}

TEST(SdlBoundedBy, ClippedByBoundedByStillClips) {
  const scene::Scene s =
      test::parse("sphere { 0, 2 bounded_by { box { -1, 1 } } clipped_by { bounded_by } }");
  ASSERT_EQ(s.objects.size(), 1u);
  scene::SurfaceHit hit;
  // The clip box's face x = -1 is no surface: the ray at y = 1.5 meets the sphere outside the box only.
  EXPECT_FALSE(s.objects[0]->intersect({{-5, 1.5, 0}, {1, 0, 0}, 0}, 1e-9, math::kInfinity, hit));
}

}  // namespace
}  // namespace snell::sdl
