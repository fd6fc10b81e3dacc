// Height field hits against the planes its samples span (POV-Ray 3.7 reference, "Height Field").
#include "snell/geometry/height_field.hpp"

#include <gtest/gtest.h>

#include "shape_checks.hpp"
#include "snell/geometry/triangle_kernel.hpp"
#include "snell/math/pcg32.hpp"

namespace snell::geometry {
namespace {

/// A width x depth grid with height(i, k) = f(x, z) at the sample's shape-space position.
template <typename F>
HeightGrid grid_of(int width, int depth, F f) {
  HeightGrid g;
  g.width = width, g.depth = depth;
  for (int k = 0; k < depth; ++k)
    for (int i = 0; i < width; ++i)
      g.heights.push_back(static_cast<float>(f(i / (width - 1.0), k / (depth - 1.0))));
  return g;
}

TEST(HeightFieldTest, FlatGridIsAPlane) {
  const HeightField hf(grid_of(5, 7, [](double, double) { return 0.5; }), false, 0);
  LocalHit hit;
  ASSERT_TRUE(hf.intersect({{0.3, 5, 0.7}, {0, -1, 0}, 0}, 1e-9, math::kInfinity, hit));
  EXPECT_NEAR(hit.t, 4.5, 1e-6);
  shape_checks::expect_near(normalize(hit.normal), {0, 1, 0}, 1e-12);
  EXPECT_NEAR(hit.uv.u, 0.3, 1e-9);
  EXPECT_NEAR(hit.uv.v, 0.7, 1e-9);
}

TEST(HeightFieldTest, RampHasTheRampsSlope) {
  // y = x over 11 x 11 samples: the normal is (-1, 1, 0) in shape space, whatever the grid spacing.
  const HeightField hf(grid_of(11, 4, [](double x, double) { return x; }), false, 0);
  LocalHit hit;
  ASSERT_TRUE(hf.intersect({{0.25, 5, 0.5}, {0, -1, 0}, 0}, 1e-9, math::kInfinity, hit));
  EXPECT_NEAR(hit.t, 4.75, 1e-6);
  shape_checks::expect_near(normalize(hit.normal), normalize(Vec3(-1, 1, 0)), 1e-6);
}

TEST(HeightFieldTest, LevelRayWalksCellsToTheRamp) {
  const HeightField hf(grid_of(11, 11, [](double x, double) { return x; }), false, 0);
  LocalHit hit;
  ASSERT_TRUE(hf.intersect({{-1, 0.37, 0.2}, {1, 0, 0}, 0}, 1e-9, math::kInfinity, hit));
  EXPECT_NEAR(hit.t, 1.37, 1e-6);
  // Diagonally across both axes.
  ASSERT_TRUE(hf.intersect({{-1, 0.37, -1}, {1, 0, 1}, 0}, 1e-9, math::kInfinity, hit));
  EXPECT_NEAR(hit.t, 1.37, 1e-6);
}

TEST(HeightFieldTest, SolidIsBelowTheSurface) {
  const HeightField hf(grid_of(6, 6, [](double x, double z) { return 0.5 * (x + z); }), false, 0);
  EXPECT_TRUE(hf.inside({0.5, 0.2, 0.5}));
  EXPECT_FALSE(hf.inside({0.5, 0.7, 0.5}));
  EXPECT_FALSE(hf.inside({1.5, 0.2, 0.5}));
  EXPECT_NEAR(hf.height(0.3, 0.5), 0.4, 1e-6);
}

TEST(HeightFieldTest, WaterLevelRaisesTheFloor) {
  const HeightField hf(grid_of(6, 6, [](double x, double) { return x; }), false, 0.5);
  LocalHit hit;
  // Cells wholly under the water are not drawn (POV-Ray: "the height field is not displayed below it").
  EXPECT_FALSE(hf.intersect({{0.1, 5, 0.5}, {0, -1, 0}, 0}, 1e-9, math::kInfinity, hit));
  ASSERT_TRUE(hf.intersect({{0.8, 5, 0.5}, {0, -1, 0}, 0}, 1e-9, math::kInfinity, hit));
  EXPECT_NEAR(hit.t, 4.2, 1e-6);
  EXPECT_NEAR(hf.height(0.1, 0.5), 0.5, 1e-6);
}

TEST(HeightFieldTest, SmoothNormalsFollowTheCurve) {
  // y = x^2 / 2: the interpolated normal at x tends to (-x, 1, 0).
  const HeightField hf(grid_of(101, 3, [](double x, double) { return 0.5 * x * x; }), true, 0);
  LocalHit hit;
  ASSERT_TRUE(hf.intersect({{0.505, 5, 0.5}, {0, -1, 0}, 0}, 1e-9, math::kInfinity, hit));
  shape_checks::expect_near(normalize(hit.shading_normal), normalize(Vec3(-0.505, 1, 0)), 1e-3);
}

TEST(HeightFieldTest, PassesShapeChecks) {
  shape_checks::check_random_rays(
      HeightField(
          grid_of(17, 9, [](double x, double z) { return 0.5 + 0.4 * std::sin(7 * x) * std::cos(5 * z); }),
          false, 0),
      false, 500);
}

TEST(HeightFieldTest, NearestHitIsTheNearestOfItsTriangles) {
  // Ridges, plateaus and pits over 70 x 53 samples (blocks of cells the walk crosses in one step where the
  // ray passes above or below them), against every cell's two triangles tested one by one.
  const HeightGrid grid = grid_of(70, 53, [](double x, double z) {
    const double ridge = 0.5 + 0.45 * std::sin(9 * x) * std::cos(7 * z);
    return x > 0.6 && z < 0.3 ? 0.2 : ridge;
  });
  const HeightField hf(grid, false, 0);
  const auto at = [&](int i, int k) {
    return Vec3(i / (grid.width - 1.0), grid.at(i, k), k / (grid.depth - 1.0));
  };
  math::Pcg32 rng(5);
  const auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * rng.next_double(); };
  int hits = 0;
  for (int n = 0; n < 3000; ++n) {
    const Vec3 origin{uniform(-0.5, 1.5), uniform(n % 3 == 0 ? 0.0 : 1.0, 2.0), uniform(-0.5, 1.5)};
    const Vec3 target{uniform(0, 1), uniform(0, 1), uniform(0, 1)};
    const Ray ray{origin, target - origin, 0};
    double nearest = math::kInfinity;
    for (int k = 0; k + 1 < grid.depth; ++k)
      for (int i = 0; i + 1 < grid.width; ++i) {
        TriangleHit t;
        if (intersect_triangle(at(i, k), at(i, k + 1), at(i + 1, k), ray, 1e-9, nearest, t)) nearest = t.t;
        if (intersect_triangle(at(i + 1, k + 1), at(i + 1, k), at(i, k + 1), ray, 1e-9, nearest, t))
          nearest = t.t;
      }
    LocalHit hit;
    const bool found = hf.intersect(ray, 1e-9, math::kInfinity, hit);
    ASSERT_EQ(found, nearest < math::kInfinity) << "ray " << n;
    if (!found) continue;
    ++hits;
    EXPECT_NEAR(hit.t, nearest, 1e-9 * (1 + nearest)) << "ray " << n;
  }
  EXPECT_GT(hits, 1500);
}

}  // namespace
}  // namespace snell::geometry
