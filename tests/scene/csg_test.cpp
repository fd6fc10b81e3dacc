// CSG against answers worked out by hand from the children's equations (POV-Ray 3.7 reference,
// "Constructive Solid Geometry": intersection keeps the points inside all children, difference the
// first child minus the others, merge the union without the surfaces inside other children).
#include "snell/scene/csg.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "snell/geometry/box.hpp"
#include "snell/geometry/disc.hpp"
#include "snell/geometry/sphere.hpp"
#include "snell/math/constants.hpp"
#include "snell/math/pcg32.hpp"
#include "snell/scene/object.hpp"

namespace snell::scene {
namespace {

using math::Bounds3;
using math::Vec3;
using ObjectPtr = std::shared_ptr<const Object>;

std::shared_ptr<Object> sphere(const Vec3& center, double radius, bool inverse = false) {
  auto o = std::make_shared<Object>();
  o->shape = std::make_shared<geometry::Sphere>(Vec3(0), radius);
  o->transform = math::Transform::translate(center);
  o->texture = material::Texture::default_texture();
  o->flags.inverse = inverse;
  return o;
}

ObjectPtr csg(CsgKind kind, std::vector<ObjectPtr> children, size_t surfaces = 0) {
  auto o = std::make_shared<Object>();
  o->texture = material::Texture::default_texture();
  o->csg = std::make_shared<Csg>(kind, std::move(children), surfaces);
  return o;
}

void expect_near(const Vec3& a, const Vec3& b, double eps = 1e-9) {
  EXPECT_NEAR(a.x, b.x, eps);
  EXPECT_NEAR(a.y, b.y, eps);
  EXPECT_NEAR(a.z, b.z, eps);
}

constexpr double kFar = math::kInfinity;

TEST(CsgTest, LensIsTheIntersectionOfTwoSpheres) {
  // Unit spheres at x = -0.5 and x = +0.5 overlap in a lens from x = -0.5 to 0.5, whose rim is the
  // circle x = 0, y^2 + z^2 = 3/4.
  const auto left = sphere({-0.5, 0, 0}, 1);
  const auto right = sphere({0.5, 0, 0}, 1);
  const ObjectPtr lens = csg(CsgKind::intersection, {left, right});
  SurfaceHit hit;
  ASSERT_TRUE(lens->intersect({{-5, 0, 0}, {1, 0, 0}, 0}, 1e-9, kFar, hit));
  EXPECT_NEAR(hit.t, 4.5, 1e-12);  // the right sphere's near side at x = -0.5
  EXPECT_EQ(hit.object, right.get());
  expect_near(hit.normal, {-1, 0, 0});
  std::vector<SurfaceHit> all;
  lens->all_hits({{-5, 0, 0}, {1, 0, 0}, 0}, 1e-9, kFar, all);
  ASSERT_EQ(all.size(), 2u);
  EXPECT_NEAR(all[1].t, 5.5, 1e-12);
  EXPECT_EQ(all[1].object, left.get());
  // Just outside the rim, a ray along x misses; just inside it hits.
  EXPECT_FALSE(lens->intersect({{-5, std::sqrt(0.75) + 1e-3, 0}, {1, 0, 0}, 0}, 1e-9, kFar, hit));
  EXPECT_TRUE(lens->intersect({{-5, std::sqrt(0.75) - 1e-3, 0}, {1, 0, 0}, 0}, 1e-9, kFar, hit));
  EXPECT_TRUE(lens->inside({0, 0.5, 0}));
  EXPECT_FALSE(lens->inside({-1, 0, 0}));
  // Bounds are the overlap of the children's boxes.
  const Bounds3 b = lens->world_bounds();
  EXPECT_NEAR(b.lo.x, -0.5, 1e-9);
  EXPECT_NEAR(b.hi.x, 0.5, 1e-9);
}

TEST(CsgTest, DifferenceShowsTheSubtractedSurfaceWithItsNormalInward) {
  // A radius-2 ball minus a radius-1 ball: a hollow shell. The inner surface belongs to the subtracted
  // (inverted) sphere and its normal points out of the shell's material, i.e. toward the centre.
  const auto outer = sphere({0, 0, 0}, 2);
  const auto hole = sphere({0, 0, 0}, 1, /*inverse=*/true);
  const ObjectPtr shell = csg(CsgKind::intersection, {outer, hole});
  std::vector<SurfaceHit> all;
  shell->all_hits({{0, 0, -5}, {0, 0, 1}, 0}, 1e-9, kFar, all);
  ASSERT_EQ(all.size(), 4u);
  const double ts[4] = {3, 4, 6, 7};
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(all[static_cast<size_t>(i)].t, ts[i], 1e-12);
  EXPECT_EQ(all[1].object, hole.get());
  expect_near(all[1].normal, {0, 0, 1});   // at z = -1, pointing to the centre
  expect_near(all[2].normal, {0, 0, -1});  // at z = +1
  // From the centre (in the hole) the first surface is the inner one.
  SurfaceHit hit;
  ASSERT_TRUE(shell->intersect({{0, 0, 0}, {1, 0, 0}, 0}, 1e-9, kFar, hit));
  EXPECT_NEAR(hit.t, 1, 1e-12);
  expect_near(hit.normal, {-1, 0, 0});
  EXPECT_FALSE(shell->inside({0, 0, 0}));
  EXPECT_TRUE(shell->inside({1.5, 0, 0}));
  // The difference's bounds are the first child's.
  const Bounds3 b = shell->world_bounds();
  expect_near(b.lo, {-2, -2, -2});
  expect_near(b.hi, {2, 2, 2});
}

TEST(CsgTest, MergeHasNoInternalSurfacesButUnionDoes) {
  const auto a = sphere({-0.5, 0, 0}, 1);
  const auto b = sphere({0.5, 0, 0}, 1);
  const Ray ray{{-5, 0, 0}, {1, 0, 0}, 0};
  std::vector<SurfaceHit> merged, unioned;
  csg(CsgKind::merge, {a, b})->all_hits(ray, 1e-9, kFar, merged);
  csg(CsgKind::union_of, {a, b})->all_hits(ray, 1e-9, kFar, unioned);
  ASSERT_EQ(merged.size(), 2u);
  EXPECT_NEAR(merged[0].t, 3.5, 1e-12);
  EXPECT_NEAR(merged[1].t, 6.5, 1e-12);
  ASSERT_EQ(unioned.size(), 4u);
  EXPECT_NEAR(unioned[1].t, 4.5, 1e-12);
  // From inside the overlap, merge's nearest surface is the far outer one.
  SurfaceHit hit;
  ASSERT_TRUE(csg(CsgKind::merge, {a, b})->intersect({{0, 0, 0}, {1, 0, 0}, 0}, 1e-9, kFar, hit));
  EXPECT_NEAR(hit.t, 1.5, 1e-12);
  EXPECT_EQ(hit.object, b.get());
}

TEST(CsgTest, ClippingChildrenOnlyCut) {
  // A unit sphere clipped by a big ball centred at x = 3 (radius 3): the clip's surface never shows, so
  // a ray along x from the left enters the sphere's remaining cap only at its far side x = +1.
  const auto ball = sphere({0, 0, 0}, 1);
  const auto clip = sphere({3, 0, 0}, 3);
  const ObjectPtr clipped = csg(CsgKind::intersection, {ball, clip}, 1);
  SurfaceHit hit;
  ASSERT_TRUE(clipped->intersect({{-5, 0, 0}, {1, 0, 0}, 0}, 1e-9, kFar, hit));
  EXPECT_NEAR(hit.t, 6, 1e-12);
  EXPECT_EQ(hit.object, ball.get());
}

TEST(CsgTest, InverseCsgFlipsNormalsAndInside) {
  auto lens = std::make_shared<Object>(*csg(CsgKind::intersection, {sphere({0, 0, 0}, 1)}));
  lens->flags.inverse = true;
  SurfaceHit hit;
  ASSERT_TRUE(lens->intersect({{-5, 0, 0}, {1, 0, 0}, 0}, 1e-9, kFar, hit));
  expect_near(hit.normal, {1, 0, 0});
  EXPECT_FALSE(lens->inside({0, 0, 0}));
  EXPECT_TRUE(lens->inside({3, 0, 0}));
}

TEST(CsgTest, NestedCsgReportsTheLeaf) {
  // (A minus B) intersected with a half-space-like big ball: the leaf hit is reported, not the node.
  const auto a = sphere({0, 0, 0}, 2);
  const auto b = sphere({0, 0, 0}, 1, true);
  const ObjectPtr shell = csg(CsgKind::intersection, {a, b});
  const auto cut = sphere({0, 0, 10}, 10);  // keeps z > ~0
  const ObjectPtr half = csg(CsgKind::intersection, {shell, cut});
  SurfaceHit hit;
  ASSERT_TRUE(half->intersect({{0, 0, -5}, {0, 0, 1}, 0}, 1e-9, kFar, hit));
  // z < 0 is cut away and the cut's surface at z = 0 lies in the hole; the hole's far side z = +1 stays.
  EXPECT_NEAR(hit.t, 6, 1e-12);
  EXPECT_EQ(hit.object, b.get());
  // At x = 1.5 the cut's surface z = 10 - sqrt(97.75) lies in the shell's material.
  ASSERT_TRUE(half->intersect({{1.5, 0, -5}, {0, 0, 1}, 0}, 1e-9, kFar, hit));
  EXPECT_NEAR(hit.t, 15 - std::sqrt(97.75), 1e-9);
  EXPECT_EQ(hit.object, cut.get());
}

// keeps() answers a child's inside() by its box where the shape says its inside lies within its bounds,
// and asks the shape otherwise: a disc's inside is its whole lower half-space (POV-Ray disc.cpp), so a box
// minus a small disc loses everything below the disc's plane, far outside the disc's own box.
TEST(CsgTest, DifferenceByADiscCutsItsWholeHalfSpace) {
  auto box = std::make_shared<Object>();
  box->shape = std::make_shared<geometry::Box>(Vec3(-2), Vec3(2));
  box->texture = material::Texture::default_texture();
  auto disc = std::make_shared<Object>();
  disc->shape = std::make_shared<geometry::Disc>(Vec3(0), Vec3(0, 1, 0), 0.1, 0);
  disc->texture = material::Texture::default_texture();
  disc->flags.inverse = true;
  const ObjectPtr cut = csg(CsgKind::intersection, {box, disc});
  EXPECT_FALSE(cut->inside({1.5, -1, 1.5}));  // below the plane, far from the disc's box
  EXPECT_TRUE(cut->inside({1.5, 1, 1.5}));
  SurfaceHit hit;
  // Down from above at x = 1.5 the box's top is the first surface. Up from below, the box's bottom face
  // lies in the cut half-space and the plane y = 0 is no surface (the disc is hit only within its radius),
  // so the first surface is the top face again, from inside.
  ASSERT_TRUE(cut->intersect({{1.5, 5, 1.5}, {0, -1, 0}, 0}, 1e-9, kFar, hit));
  EXPECT_NEAR(hit.t, 3, 1e-12);
  ASSERT_TRUE(cut->intersect({{1.5, -5, 1.5}, {0, 1, 0}, 0}, 1e-9, kFar, hit));
  EXPECT_NEAR(hit.t, 7, 1e-12);
  // A sphere cut away is answered by its box outside it, the same as by the sphere.
  const ObjectPtr shell = csg(CsgKind::intersection, {sphere({0, 0, 0}, 2), sphere({0, 0, 0}, 1, true)});
  EXPECT_TRUE(shell->inside({1.9, 0, 0}));
  EXPECT_FALSE(shell->inside({0.5, 0, 0}));
  ASSERT_TRUE(shell->intersect({{-5, 0, 0}, {1, 0, 0}, 0}, 1e-9, kFar, hit));
  EXPECT_NEAR(hit.t, 3, 1e-12);
}

// POV-Ray inverts a CSG object by inverting its children, and an inverted union becomes the intersection
// of the inverted children (csg.cpp, CSGUnion::Invert): the inner surfaces a union keeps (each child's
// surface inside the other) are gone once it is inverted, as in chess2.pov's crowns, where a ring of
// overlapping spheres is cut out of a cone. Here a ball of radius 3 minus the union of two unit spheres at
// x = -0.5 and 0.5: along the x axis the cavity's walls are at x = -1.5 and 1.5 only; the union's own inner
// surfaces at x = -0.5 and 0.5 are not surfaces of the difference. The same holds one level down, for a
// union inside an inverted intersection.
TEST(CsgTest, InvertedUnionLosesItsInnerSurfaces) {
  const ObjectPtr pair = csg(CsgKind::union_of, {sphere({-0.5, 0, 0}, 1), sphere({0.5, 0, 0}, 1)});
  auto cut_away = std::make_shared<Object>(*pair);
  cut_away->flags.inverse = true;
  const ObjectPtr ball = csg(CsgKind::intersection, {sphere({0, 0, 0}, 3), cut_away});
  std::vector<SurfaceHit> all;
  ball->all_hits({{-5, 0, 0}, {1, 0, 0}, 0}, 1e-9, kFar, all);
  ASSERT_EQ(all.size(), 4u);
  const double ts[4] = {2, 3.5, 6.5, 8};
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(all[static_cast<size_t>(i)].t, ts[i], 1e-12);
  // The union itself keeps its inner surfaces.
  all.clear();
  pair->all_hits({{-5, 0, 0}, {1, 0, 0}, 0}, 1e-9, kFar, all);
  EXPECT_EQ(all.size(), 4u);
  // A union inside an intersection that is inverted as a whole is inverted with it.
  auto outer = std::make_shared<Object>(*csg(CsgKind::intersection, {pair, sphere({0, 0, 0}, 10)}));
  outer->flags.inverse = true;
  const ObjectPtr shell = csg(CsgKind::intersection, {sphere({0, 0, 0}, 3), outer});
  all.clear();
  shell->all_hits({{-5, 0, 0}, {1, 0, 0}, 0}, 1e-9, kFar, all);
  ASSERT_EQ(all.size(), 4u);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(all[static_cast<size_t>(i)].t, ts[i], 1e-12);
}

std::shared_ptr<Object> box(const Vec3& lo, const Vec3& hi, const math::Transform& placement,
                            bool inverse = false) {
  auto o = std::make_shared<Object>();
  o->shape = std::make_shared<geometry::Box>(lo, hi);
  o->transform = placement;
  o->texture = material::Texture::default_texture();
  o->flags.inverse = inverse;
  return o;
}

// A difference of boxes alone takes its own path (csg_boxes.cpp); a sphere around everything, as a
// clipping child, changes nothing but sends the same CSG down the general path. Both must find the same
// hits, faces and answers for shadow rays, in csg_granite.pov's box frame (rotated, so the boxes keep
// their transforms) and where faces coincide (a slot cut exactly to the block's faces), on random rays.
TEST(CsgTest, DifferenceOfBoxesHitsAsTheGeneralPath) {
  const math::Transform turn = math::Transform::rotate_xyz_degrees({10, 45, 0});
  const std::vector<ObjectPtr> children{
      box(Vec3(-1.5), Vec3(1.5), turn), box({-1.51, -1.25, -1.25}, {1.51, 1.25, 1.25}, turn, true),
      box({-1.25, -1.51, -1.25}, {1.25, 1.51, 1.25}, turn, true),
      box({-1.25, -1.25, -1.51}, {1.25, 1.25, 1.51}, turn, true),
      box({-0.5, -1.5, -0.5}, {0.5, 0, 1.5}, turn, true)};  // faces on the block's bottom and front
  std::vector<ObjectPtr> clipped = children;
  clipped.push_back(sphere({0, 0, 0}, 100));
  const ObjectPtr fast = csg(CsgKind::intersection, children),
                  general = csg(CsgKind::intersection, clipped, 5);
  math::Pcg32 rng(11);
  int hits = 0;
  for (int i = 0; i < 20000; ++i) {
    const auto coordinate = [&] { return 8 * rng.next_double() - 4; };
    const Vec3 origin(coordinate(), coordinate(), coordinate());
    Vec3 target(coordinate() / 2, coordinate() / 2, coordinate() / 2);
    // A quarter of the rays run exactly along the axes of the boxes' space, grazing faces and edges.
    if (i % 4 == 0)
      target = origin + turn.vector(Vec3(i % 3 == 0 ? 1 : 0, i % 3 == 1 ? 1 : 0, i % 3 == 2 ? 1 : 0));
    const math::Ray ray{origin, target - origin, 0};
    SurfaceHit a, b;
    const bool found = fast->intersect(ray, 1e-9, kFar, a);
    ASSERT_EQ(found, general->intersect(ray, 1e-9, kFar, b)) << i;
    EXPECT_EQ(fast->blocks(ray, 1e-9, 1.0), general->blocks(ray, 1e-9, 1.0)) << i;
    if (!found) continue;
    ++hits;
    EXPECT_EQ(a.t, b.t) << i;
    EXPECT_EQ(a.object, b.object) << i;
    EXPECT_EQ(a.normal, b.normal) << i;
    EXPECT_EQ(a.uv.u, b.uv.u) << i;
  }
  EXPECT_GT(hits, 2000);
}

TEST(CsgTest, EmptyCsgIsAnError) {
  EXPECT_THROW(Csg(CsgKind::merge, {}), std::invalid_argument);
}

}  // namespace
}  // namespace snell::scene
