// Bicubic patch tessellation against Bezier patch identities (POV-Ray 3.7 reference, "Bicubic Patch").
#include "snell/geometry/bicubic_patch.hpp"

#include <gtest/gtest.h>

#include "shape_checks.hpp"

namespace snell::geometry {
namespace {

/// A flat patch: control points on the grid x = j, y = i in the plane z = 0 (a bilinear map stays linear).
BezierPoints flat_patch() {
  BezierPoints p;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) p[static_cast<std::size_t>(4 * i + j)] = Vec3(j, i, 0);
  return p;
}

TEST(BicubicPatchTest, CornersAreControlPointsAndFlatStaysFlat) {
  BezierPoints p = flat_patch();
  p[5] = Vec3(1, 1, 3);  // an inner control point pulls the middle up, not the corners
  shape_checks::expect_near(bezier_patch_point(p, 0, 0), p[0], 1e-12);
  shape_checks::expect_near(bezier_patch_point(p, 1, 1), p[15], 1e-12);
  // Bernstein weight of the inner point (1, 1) at u = v = 1/2 is (3/8)^2.
  EXPECT_NEAR(bezier_patch_point(p, 0.5, 0.5).z, 3 * 9.0 / 64, 1e-12);
  shape_checks::expect_near(bezier_patch_point(flat_patch(), 0.25, 0.5), Vec3(0.75, 1.5, 0), 1e-12);
}

TEST(BicubicPatchTest, TessellationHasTwoTrianglesPerQuadAndHitsThePlane) {
  const MeshData data = tessellate_bicubic_patch(flat_patch(), 2, 3);
  EXPECT_EQ(data.faces.size(), 2u * 4 * 8);
  const Mesh mesh(data);
  LocalHit hit;
  ASSERT_TRUE(mesh.intersect({{1.3, 2.1, -5}, {0, 0, 1}, 0}, 1e-9, math::kInfinity, hit));
  EXPECT_NEAR(hit.t, 5, 1e-9);
  EXPECT_NEAR(std::fabs(normalize(hit.normal).z), 1, 1e-9);
}

}  // namespace
}  // namespace snell::geometry
