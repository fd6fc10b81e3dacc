// CSG, clipped_by and quadric as the parser builds them (POV-Ray 3.7 reference, "Constructive Solid
// Geometry", "Clipped_By", "Quadric").
#include <gtest/gtest.h>

#include <cmath>

#include "sdl_test_util.hpp"
#include "snell/math/constants.hpp"
#include "snell/scene/csg.hpp"

namespace snell::sdl {
namespace {

using math::Vec3;

TEST(SdlCsg, DeclaredDifferenceWithChildTexturesAndTransforms) {
  const scene::Scene s = test::parse(R"(
    #declare Shell = difference {
      sphere { 0, 2 }
      sphere { 0, 1 pigment { rgb <1, 0, 0> } }
      pigment { rgb <0, 0, 1> }
    }
    object { Shell translate <10, 0, 0> }
  )");
  ASSERT_EQ(s.objects.size(), 1u);
  const scene::Object& shell = *s.objects[0];
  ASSERT_TRUE(shell.csg);
  EXPECT_EQ(shell.csg->kind(), scene::CsgKind::intersection);
  // Along x through the centre at x = 10: outer at 8, inner (hole) at 9.
  scene::SurfaceHit hit;
  ASSERT_TRUE(shell.intersect({{0, 0, 0}, {1, 0, 0}, 0}, 1e-9, math::kInfinity, hit));
  EXPECT_NEAR(hit.t, 8, 1e-9);
  EXPECT_EQ(test::solid_color(*hit.object).rgb.b, 1);  // the outer sphere inherits the CSG's pigment
  ASSERT_TRUE(shell.intersect({{0, 0, 0}, {1, 0, 0}, 0}, 8.5, math::kInfinity, hit));
  EXPECT_NEAR(hit.t, 9, 1e-9);
  EXPECT_EQ(test::solid_color(*hit.object).rgb.r, 1);  // the hole keeps its own
  EXPECT_GT(hit.normal.x, 0.99);  // the subtracted surface faces the hole's centre (at +x)
  EXPECT_TRUE(shell.inside({11.5, 0, 0}));
  EXPECT_FALSE(shell.inside({10, 0, 0}));
}

TEST(SdlCsg, MergeIntersectionAndUnionInsideCsg) {
  const scene::Scene s = test::parse(R"(
    merge { sphere { -0.5*x, 1 } sphere { 0.5*x, 1 } }
    intersection { union { sphere { 0, 1 } sphere { 3*x, 1 } } box { -10, <2, 10, 10> } }
    union { sphere { 0, 1 } sphere { 5*y, 1 } }
  )");
  // The plain union flattens into two objects; the CSG objects stay one each.
  ASSERT_EQ(s.objects.size(), 4u);
  ASSERT_TRUE(s.objects[0]->csg);
  EXPECT_EQ(s.objects[0]->csg->kind(), scene::CsgKind::merge);
  ASSERT_TRUE(s.objects[1]->csg);
  EXPECT_EQ(s.objects[1]->csg->children()[0]->csg->kind(), scene::CsgKind::union_of);
  // The box cuts the second sphere of the nested union away: its x extent ends at 2.
  EXPECT_NEAR(s.objects[1]->world_bounds().hi.x, 2, 1e-9);
  EXPECT_FALSE(s.objects[2]->csg);
}

TEST(SdlCsg, ClippedByMovesWithLaterTransforms) {
  const scene::Scene s = test::parse(R"(
    sphere { 0, 1 clipped_by { plane { x, 0 } } translate <0, 0, 5> }
  )");
  ASSERT_EQ(s.objects.size(), 1u);
  const scene::Object& o = *s.objects[0];
  scene::SurfaceHit hit;
  // The plane keeps x < 0: along +x at z = 5 the near side at x = -1 stays, the far side at x = +1
  // is gone, and the plane itself shows no surface.
  std::vector<scene::SurfaceHit> all;
  o.all_hits({{-5, 0, 5}, {1, 0, 0}, 0}, 1e-9, math::kInfinity, all);
  ASSERT_EQ(all.size(), 1u);
  EXPECT_NEAR(all[0].t, 4, 1e-9);
  EXPECT_FALSE(o.intersect({{5, 0, 5}, {1, 0, 0}, 0}, 1e-9, math::kInfinity, hit));
}

TEST(SdlCsg, QuadricFromShapesOldInc) {
  const scene::Scene s = test::parse(R"(
    #include "shapes_old.inc"
    object { Ellipsoid scale <2, 1, 1> }
    quadric { <1, 1, 1>, <0, 0, 0>, <0, 0, 0>, -4 }
  )");
  ASSERT_EQ(s.objects.size(), 2u);
  scene::SurfaceHit hit;
  ASSERT_TRUE(s.objects[0]->intersect({{-5, 0, 0}, {1, 0, 0}, 0}, 1e-9, math::kInfinity, hit));
  EXPECT_NEAR(hit.t, 3, 1e-9);
  ASSERT_TRUE(s.objects[1]->intersect({{0, -5, 0}, {0, 1, 0}, 0}, 1e-9, math::kInfinity, hit));
  EXPECT_NEAR(hit.t, 3, 1e-9);
}

TEST(SdlCsg, Errors) {
  EXPECT_NE(test::error_of("sphere { 0, 1 clipped_by { } }").find("clipped_by needs"), std::string::npos);
  EXPECT_NE(test::error_of("quadric { <0,0,0>, <0,0,0>, <0,0,0>, 1 }").find("quadric"), std::string::npos);
  EXPECT_NE(test::error_of("difference { sphere { 0, 1 }").find("end of file"), std::string::npos);
}

}  // namespace
}  // namespace snell::sdl
