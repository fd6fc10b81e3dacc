#include "snell/geometry/prism.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "shape_checks.hpp"

using namespace snell::geometry;
using snell::geometry::shape_checks::expect_near;
using snell::math::kInfinity;

namespace {

std::vector<Vec2> square(double h) {
  return {{-h, -h}, {h, -h}, {h, h}, {-h, h}, {-h, -h}};
}

Prism linear_prism(const std::vector<Vec2>& points, double h1, double h2, Sweep sweep = Sweep::linear) {
  return Prism(Outline(prism_pieces(SplineKind::linear, points)), h1, h2, sweep, false);
}

// Knots of a regular octagon of radius 1, starting at angle 0.
Vec2 knot(int i) {
  const double a = (i % 8) * snell::math::kPi / 4;
  return {std::cos(a), std::sin(a)};
}

}  // namespace

TEST(PrismTest, SquareWallsAndCaps) {
  const Prism prism = linear_prism(square(1), 0, 2);
  HitList hits;
  prism.all_hits({{-5, 1, 0.3}, {1, 0, 0}, 0}, 0, kInfinity, hits);
  ASSERT_EQ(hits.size(), 2u);
  EXPECT_NEAR(hits[0].t, 4, 1e-12);
  EXPECT_NEAR(hits[1].t, 6, 1e-12);
  expect_near(hits[0].normal, {-1, 0, 0}, 1e-12);
  expect_near(hits[1].normal, {1, 0, 0}, 1e-12);
  hits.clear();
  prism.all_hits({{0.2, 5, -0.4}, {0, -2, 0}, 0}, 0, kInfinity, hits);
  ASSERT_EQ(hits.size(), 2u);
  EXPECT_NEAR(hits[0].t, 1.5, 1e-12);
  EXPECT_NEAR(hits[1].t, 2.5, 1e-12);
  expect_near(hits[0].normal, {0, 1, 0}, 1e-12);
  expect_near(hits[1].normal, {0, -1, 0}, 1e-12);
  EXPECT_TRUE(prism.inside({0.9, 1.9, -0.9}));
  EXPECT_FALSE(prism.inside({0.9, 2.1, -0.9}));
  EXPECT_FALSE(prism.inside({1.1, 1, 0}));
}

TEST(PrismTest, EvenOddHole) {
  std::vector<Vec2> points = square(2);
  for (const Vec2& p : square(1)) points.push_back(p);
  const Prism prism = linear_prism(points, 0, 1);
  EXPECT_EQ(prism_pieces(SplineKind::linear, points).size(), 8u);
  LocalHit hit;
  EXPECT_FALSE(prism.intersect({{0, 5, 0}, {0, -1, 0}, 0}, 0, kInfinity, hit));  // down the hole
  ASSERT_TRUE(prism.intersect({{1.5, 5, 0}, {0, -1, 0}, 0}, 0, kInfinity, hit));
  EXPECT_NEAR(hit.t, 4, 1e-12);
  // Along x through the hole: outer wall, hole wall (normal facing the hole), hole wall, outer wall.
  HitList hits;
  prism.all_hits({{-5, 0.5, 0}, {1, 0, 0}, 0}, 0, kInfinity, hits);
  ASSERT_EQ(hits.size(), 4u);
  const double expected[] = {3, 4, 6, 7};
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(hits[static_cast<size_t>(i)].t, expected[i], 1e-12);
  expect_near(hits[1].normal, {1, 0, 0}, 1e-12);
  EXPECT_FALSE(prism.inside({0, 0.5, 0}));
  EXPECT_TRUE(prism.inside({1.5, 0.5, 1.5}));
}

TEST(PrismTest, ConicSweepScalesWithHeight) {
  // Outline scaled by y: at y = 0.75 the square's half width is 0.75; its walls lie in x = +-y.
  const Prism prism = linear_prism(square(1), 0.5, 1, Sweep::conic);
  HitList hits;
  prism.all_hits({{-5, 0.75, 0}, {1, 0, 0}, 0}, 0, kInfinity, hits);
  ASSERT_EQ(hits.size(), 2u);
  EXPECT_NEAR(hits[0].t, 4.25, 1e-12);
  EXPECT_NEAR(hits[1].t, 5.75, 1e-12);
  expect_near(normalize(hits[1].normal), Vec3(1, -1, 0) / std::sqrt(2.0), 1e-12);
  const Bounds3 b = prism.bounds();
  expect_near(b.lo, {-1, 0.5, -1}, 1e-12);
  expect_near(b.hi, {1, 1, 1}, 1e-12);
  EXPECT_TRUE(prism.inside({0.55, 0.6, 0}));
  EXPECT_FALSE(prism.inside({0.65, 0.6, 0}));
}

TEST(PrismTest, CurvedSplinesPassThroughTheirKnots) {
  // Quadratic: a leading control point, then knots; cubic: control points at both ends.
  std::vector<Vec2> quadratic{knot(7)}, cubic{knot(7)};
  for (int i = 0; i <= 8; ++i) quadratic.push_back(knot(i));
  for (int i = 0; i <= 9; ++i) cubic.push_back(knot(i));
  std::vector<Vec2> bezier;  // straight Bezier pieces: control points on the chords
  for (int i = 0; i < 8; ++i) {
    const Vec2 a = knot(i), b = knot(i + 1);
    bezier.insert(bezier.end(), {a,
                                 {a.u + (b.u - a.u) / 3, a.v + (b.v - a.v) / 3},
                                 {a.u + 2 * (b.u - a.u) / 3, a.v + 2 * (b.v - a.v) / 3},
                                 b});
  }
  Vec2 first;
  EXPECT_TRUE(outline_closed(SplineKind::quadratic, quadratic, first));
  EXPECT_TRUE(outline_closed(SplineKind::cubic, cubic, first));
  EXPECT_TRUE(outline_closed(SplineKind::bezier, bezier, first));
  const std::pair<SplineKind, std::vector<Vec2>> cases[] = {
      {SplineKind::quadratic, quadratic}, {SplineKind::cubic, cubic}, {SplineKind::bezier, bezier}};
  for (const auto& [kind, points] : cases) {
    const Prism prism(Outline(prism_pieces(kind, points)), -1, 1, Sweep::linear, false);
    EXPECT_EQ(prism_pieces(kind, points).size(), 8u);
    HitList hits;
    prism.all_hits({{-5, 0, 0}, {1, 0, 0}, 0}, 0, kInfinity, hits);
    ASSERT_EQ(hits.size(), 2u);
    EXPECT_NEAR(hits[0].t, 4, 1e-9);  // the knots at angle 180 and 0
    EXPECT_NEAR(hits[1].t, 6, 1e-9);
    EXPECT_GT(normalize(hits[1].normal).x, 0.9);
    shape_checks::check_random_rays(prism, true, 500);
  }
}

TEST(PrismTest, UnclosedLinearOutlineReportsItsStart) {
  const std::vector<Vec2> points{{0, 0}, {1, 0}, {1, 1}};
  Vec2 first{9, 9};
  EXPECT_FALSE(outline_closed(SplineKind::linear, points, first));
  EXPECT_EQ(first.u, 0);
  EXPECT_EQ(first.v, 0);
}

TEST(PrismTest, OpenPrismHasNoCaps) {
  const Prism prism(Outline(prism_pieces(SplineKind::linear, square(1))), 0, 2, Sweep::linear, true);
  LocalHit hit;
  EXPECT_FALSE(prism.intersect({{0, 5, 0}, {0, -1, 0}, 0}, 0, kInfinity, hit));
}

TEST(PrismTest, RandomRays) {
  shape_checks::check_random_rays(linear_prism(square(1), 0, 2), true);
  shape_checks::check_random_rays(linear_prism({{0, 0}, {2, 0}, {0, 1}, {0, 0}}, -1, 3, Sweep::conic), true);
}
