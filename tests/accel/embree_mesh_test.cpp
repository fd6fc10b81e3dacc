// Meshes walked by Embree as native float triangles (accel/embree_meshes.hpp) must give the hits of the
// double-precision brute force: same object, same face, same t, also for many instances of one mesh.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "accel_test_support.hpp"
#include "snell/accel/embree_meshes.hpp"
#include "snell/geometry/mesh.hpp"

namespace snell::accel_test {
namespace {

/// A UV sphere of radius 1 with `rings` x `segments` quads split into triangles.
std::shared_ptr<const geometry::Mesh> uv_sphere(int rings, int segments) {
  geometry::MeshData d;
  for (int r = 0; r <= rings; ++r) {
    const double theta = std::numbers::pi * r / rings;
    for (int s = 0; s < segments; ++s) {
      const double phi = 2 * std::numbers::pi * s / segments;
      d.vertices.push_back(
          {std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)});
    }
  }
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      const int a = r * segments + s, b = r * segments + (s + 1) % segments;
      const int c = a + segments, e = b + segments;
      if (r > 0) d.faces.push_back({a, b, c});
      if (r < rings - 1) d.faces.push_back({b, e, c});
    }
  return std::make_shared<geometry::Mesh>(std::move(d));
}

/// 40 objects showing one UV sphere: 528 faces (placed in world space 40 times) or, with `large`, 3,744
/// faces (beyond kWorldMeshTriangles together: instances of one copy).
scene::Scene instanced_scene(uint64_t seed, bool large = false) {
  math::Pcg32 rng(seed);
  scene::Scene s = random_scene(seed, 20);
  const auto mesh = large ? uv_sphere(40, 48) : uv_sphere(12, 24);
  for (int i = 0; i < 40; ++i) {
    const Transform t = Transform::translate(uniform_vec(rng, -10, 10)) *
                        Transform::rotate_xyz_degrees(uniform_vec(rng, 0, 360)) *
                        Transform::scale(uniform_vec(rng, 0.2, 2));
    auto o = make_object(mesh, t);
    o->flags.no_shadow = rng.next_double() < 0.2;
    o->flags.no_image = rng.next_double() < 0.2;
    s.objects.push_back(o);
  }
  return s;
}

void expect_brute_force_hits(const scene::Scene& s) {
  const auto embree = accel::make_accelerator("embree", s);
  const auto brute = accel::make_accelerator("none", s);
  EXPECT_EQ(embree->stats().mesh_instances, 40u);
  math::Pcg32 rng(11);
  int hits = 0, same_face = 0;
  const int rays = 4000;
  for (int i = 0; i < rays; ++i) {
    const math::Ray ray{uniform_vec(rng, -14, 14), normalize(uniform_vec(rng, -1, 1)), 0};
    const RayKind kind = kKinds[i % 4];
    scene::SurfaceHit he, hb;
    const bool fe = embree->intersect(ray, 1e-6, 1e30, kind, he);
    const bool fb = brute->intersect(ray, 1e-6, 1e30, kind, hb);
    ASSERT_EQ(fe, fb) << "ray " << i;
    if (!fe) continue;
    ++hits;
    ASSERT_EQ(he.object, hb.object) << "ray " << i;
    EXPECT_NEAR(he.t, hb.t, 1e-9 * hb.t) << "ray " << i;
    EXPECT_NEAR(length(he.normal - hb.normal), 0, 1e-12);
    same_face += he.part == hb.part;
  }
  EXPECT_GT(hits, rays / 2);
  EXPECT_EQ(same_face, hits);
}

TEST(EmbreeMeshTest, InstancedNativeMeshesGiveTheBruteForceHits) {
  // Large: one copy of the triangles, instanced.
  const scene::Scene large = instanced_scene(7, true);
  EXPECT_EQ(accel::make_accelerator("embree", large)->stats().native_triangles,
            uv_sphere(40, 48)->data().faces.size());
  expect_brute_force_hits(large);
}

TEST(EmbreeMeshTest, SmallMeshesPlacedInWorldSpaceGiveTheBruteForceHits) {
  // Small: each object's copy placed in world space in the top scene.
  const scene::Scene small = instanced_scene(7);
  EXPECT_EQ(accel::make_accelerator("embree", small)->stats().native_triangles,
            40 * uv_sphere(12, 24)->data().faces.size());
  expect_brute_force_hits(small);
}

// Occlusion walks the instanced float triangles too: the filter redoes each in double and Embree stops
// at the first one it accepts.
TEST(EmbreeMeshTest, OccluderOfNativeMeshesAgreesWithBruteForce) {
  for (const bool large : {false, true}) {
    const scene::Scene s = instanced_scene(9, large);
    const auto embree = accel::make_accelerator("embree", s);
    const auto brute = accel::make_accelerator("none", s);
    math::Pcg32 rng(13);
    int blocked = 0;
    for (int i = 0; i < 4000; ++i) {
      const math::Ray ray{uniform_vec(rng, -14, 14), normalize(uniform_vec(rng, -1, 1)), 0};
      const RayKind kind = kKinds[i % 4];
      const double t_max = i % 2 ? 1e30 : uniform(rng, 0.5, 15);
      scene::SurfaceHit hb;
      const bool fb = brute->intersect(ray, 1e-6, t_max, kind, hb);
      const scene::Object* o = embree->occluder(ray, 1e-6, t_max, kind);
      ASSERT_EQ(o != nullptr, fb) << "ray " << i;
      if (!o) continue;
      ++blocked;
      scene::SurfaceHit own;
      EXPECT_TRUE(o->visible_to(kind) && o->intersect(ray, 1e-6, t_max, own)) << "ray " << i;
    }
    EXPECT_GT(blocked, 500);
  }
}

TEST(EmbreeMeshTest, SmallMeshesStayUserGeometry) {
  scene::Scene s;
  s.objects.push_back(make_object(uv_sphere(2, 3)));
  ASSERT_LT(uv_sphere(2, 3)->data().faces.size(), accel::kNativeMeshMinFaces);
  EXPECT_EQ(accel::make_accelerator("embree", s)->stats().mesh_instances, 0u);
}

}  // namespace
}  // namespace snell::accel_test
