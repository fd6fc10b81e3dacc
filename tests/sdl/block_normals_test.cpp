// Block patterns in normals (POV-Ray 3.7 reference, "Block Patterns"): a normal per block, or the block
// number as a bump height that steps at the blocks' edges.
#include <gtest/gtest.h>

#include "sdl_test_util.hpp"

using namespace snell;

namespace {

math::Vec3 bent(const std::string& normal_block, const math::Vec3& p) {
  const scene::Scene s = sdl::test::parse("plane { y, 0 " + normal_block + " }");
  material::PatternPoint point;
  point.p = p;
  return s.objects.front()->texture->normal->perturb({0, 1, 0}, point);
}

}  // namespace

TEST(BlockNormals, EachBlockBendsByItsOwnNormal) {
  const std::string n = "normal { checker normal { gradient x, 1 } normal { gradient z, 1 } }";
  const math::Vec3 a = bent(n, {0.5, 0.5, 0.5});  // block 0: gradient x tilts the normal in x
  const math::Vec3 b = bent(n, {1.5, 0.5, 0.5});  // block 1: gradient z tilts it in z
  EXPECT_GT(std::abs(a.x), 1e-3);
  EXPECT_NEAR(a.z, 0, 1e-9);
  EXPECT_GT(std::abs(b.z), 1e-3);
  EXPECT_NEAR(b.x, 0, 1e-9);
  EXPECT_NEAR(math::length(a), 1, 1e-12);
}

TEST(BlockNormals, WithoutEntriesTheSurfaceStepsOnlyAtBlockEdges) {
  const std::string n = "normal { checker 0.8 }";
  const math::Vec3 inside = bent(n, {0.5, 0.5, 0.5});
  const math::Vec3 edge = bent(n, {1.001, 0.5, 0.5});
  EXPECT_NEAR(inside.y, 1, 1e-12);
  EXPECT_GT(std::abs(edge.x), 1e-3);
}

TEST(BlockNormals, ObjectPatternTakesItsNormalsInsideItsBraces) {
  const std::string n =
      "normal { object { sphere { 0, 1 } normal { gradient x, 1 } normal { gradient z, 1 } } }";
  EXPECT_GT(std::abs(bent(n, {0, 0, 0}).z), 1e-3);
  EXPECT_GT(std::abs(bent(n, {3, 0, 0}).x), 1e-3);
}
