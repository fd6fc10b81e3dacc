// Object::blocks is the occlusion form of Object::intersect (shadow rays): for any ray and window it
// must answer exactly whether intersect finds a hit, for plain shapes under transforms and for CSG.
#include <gtest/gtest.h>

#include <memory>

#include "snell/geometry/box.hpp"
#include "snell/geometry/cone.hpp"
#include "snell/geometry/plane.hpp"
#include "snell/geometry/sphere.hpp"
#include "snell/math/pcg32.hpp"
#include "snell/scene/csg.hpp"
#include "snell/scene/object.hpp"

namespace snell::scene {
namespace {

using math::Vec3;
using ObjectPtr = std::shared_ptr<const Object>;

std::shared_ptr<Object> plain(std::shared_ptr<const geometry::Shape> shape, const math::Transform& t) {
  auto o = std::make_shared<Object>();
  o->shape = std::move(shape);
  o->transform = t;
  o->texture = material::Texture::default_texture();
  return o;
}

double uniform(math::Pcg32& rng, double lo, double hi) {
  return lo + (hi - lo) * rng.next_double();
}

TEST(ObjectBlocksTest, AgreesWithIntersectOnRandomRaysAndWindows) {
  const auto box =
      plain(std::make_shared<geometry::Box>(Vec3(-1), Vec3(1)),
            math::Transform::rotate_xyz_degrees({20, 35, 10}) * math::Transform::scale({1, 2, 0.5}));
  const auto ball =
      plain(std::make_shared<geometry::Sphere>(Vec3(0), 1), math::Transform::translate({0.8, 0, 0}));
  const auto floor = plain(std::make_shared<geometry::Plane>(Vec3(0, 1, 0), -0.5), math::Transform());
  auto difference = std::make_shared<Object>();
  difference->texture = material::Texture::default_texture();
  auto hole = plain(std::make_shared<geometry::Sphere>(Vec3(0), 1), math::Transform::translate({0.8, 0, 0}));
  hole->flags.inverse = true;
  difference->csg = std::make_shared<Csg>(CsgKind::intersection, std::vector<ObjectPtr>{box, hole});
  const auto cone = plain(std::make_shared<geometry::Cone>(Vec3(0, -1, 0), 1.0, Vec3(0, 1, 0), 0.3, false),
                          math::Transform::translate({-0.5, 0.2, 0.3}));
  // CSG of every kind, nested, and inverted (Csg::crosses answers these without building hits).
  const auto csg = [](CsgKind kind, std::vector<ObjectPtr> children, bool inverse = false) {
    auto o = std::make_shared<Object>();
    o->texture = material::Texture::default_texture();
    o->csg = std::make_shared<Csg>(kind, std::move(children));
    o->flags.inverse = inverse;
    return o;
  };
  const auto merged = csg(CsgKind::merge, {box, ball, cone});
  const auto joined = csg(CsgKind::union_of, {difference, ball, cone});
  const auto inverted_union = csg(CsgKind::union_of, {box, ball}, true);
  const auto nested = csg(CsgKind::intersection, {merged, csg(CsgKind::union_of, {ball, cone})});
  const std::vector<ObjectPtr> objects{box,    ball,   floor,          difference, cone,
                                       merged, joined, inverted_union, nested};

  math::Pcg32 rng(3, 5);
  int blocked = 0, open = 0;
  for (int i = 0; i < 20000; ++i) {
    const Vec3 origin{uniform(rng, -3, 3), uniform(rng, -3, 3), uniform(rng, -3, 3)};
    const Vec3 dir = normalize(Vec3{uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)});
    const double t_min = uniform(rng, 0, 1), t_max = t_min + uniform(rng, 0, 4);
    const math::Ray ray{origin, dir, 0};
    for (const ObjectPtr& o : objects) {
      SurfaceHit hit;
      const bool expected = o->intersect(ray, t_min, t_max, hit);
      ASSERT_EQ(o->blocks(ray, t_min, t_max), expected) << "ray " << i;
      (expected ? blocked : open) += 1;
    }
  }
  // Both answers occur often, so the agreement means something.
  EXPECT_GT(blocked, 10000);
  EXPECT_GT(open, 10000);
}

}  // namespace
}  // namespace snell::scene
