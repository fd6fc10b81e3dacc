#include "snell/geometry/mesh.hpp"

#include <gtest/gtest.h>

#include <chrono>

#include "shape_checks.hpp"
#include "snell/geometry/box.hpp"
#include "snell/geometry/triangle_kernel.hpp"
#include "snell/math/pcg32.hpp"

using namespace snell::geometry;
using snell::geometry::shape_checks::expect_near;
using snell::math::kInfinity;

namespace {
// The cube [-1,1]^3 as 12 outward-wound triangles.
MeshData cube_mesh() {
  MeshData m;
  for (int i = 0; i < 8; ++i)
    m.vertices.push_back({i & 1 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0, i & 4 ? 1.0 : -1.0});
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    m.faces.push_back({q[0], q[1], q[2]});
    m.faces.push_back({q[0], q[2], q[3]});
  }
  return m;
}

// A UV sphere of radius 1 with per-vertex normals, 2 * rings * segments triangles (minus the poles' slivers).
MeshData sphere_mesh(int rings, int segments) {
  MeshData m;
  for (int i = 0; i <= rings; ++i) {
    const double theta = snell::math::kPi * i / rings;
    for (int j = 0; j < segments; ++j) {
      const double phi = 2 * snell::math::kPi * j / segments;
      m.vertices.push_back(
          {std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)});
    }
  }
  m.normals = m.vertices;
  for (int i = 0; i < rings; ++i) {
    for (int j = 0; j < segments; ++j) {
      const int a = i * segments + j, b = i * segments + (j + 1) % segments;
      const int c = a + segments, d = b + segments;
      m.faces.push_back({a, c, b});
      m.faces.push_back({b, c, d});
    }
  }
  return m;
}
}  // namespace

TEST(MeshTest, CubeMeshMatchesBox) {
  MeshData data = cube_mesh();
  data.inside_vector = Vec3(0.3, 1, 0.2);
  const Mesh mesh(std::move(data));
  const Box box({-1, -1, -1}, {1, 1, 1});
  snell::math::Pcg32 rng(7);
  for (int i = 0; i < 500; ++i) {
    const Vec3 o = 4 * shape_checks::random_unit(rng);
    const Ray ray{o, 0.5 * rng.next_double() * shape_checks::random_unit(rng) - 0.3 * o, 0};
    HitList mh, bh;
    mesh.all_hits(ray, 1e-9, kInfinity, mh);
    box.all_hits(ray, 1e-9, kInfinity, bh);
    if (bh.size() == 2 && bh[1].t - bh[0].t > 1e-6) {
      ASSERT_GE(mh.size(), 2u);
      EXPECT_NEAR(mh.front().t, bh[0].t, 1e-9);
      EXPECT_NEAR(mh.back().t, bh[1].t, 1e-9);
      expect_near(normalize(mh.front().normal), bh[0].normal, 1e-9);
    }
  }
  EXPECT_TRUE(mesh.inside({0.1, 0.2, 0.3}));
  EXPECT_FALSE(mesh.inside({1.5, 0.2, 0.3}));
  shape_checks::check_random_rays(mesh, false);
}

TEST(MeshTest, NoInsideVectorMeansNoInside) {
  const Mesh mesh(cube_mesh());
  EXPECT_FALSE(mesh.inside({0, 0, 0}));
}

TEST(MeshTest, SmoothNormalsAndFaceIndex) {
  const Mesh mesh(sphere_mesh(16, 32));
  LocalHit hit;
  ASSERT_TRUE(mesh.intersect({{0.1, 0.2, -5}, {0, 0, 1}, 0}, 0, kInfinity, hit));
  EXPECT_GE(hit.part, 0);
  EXPECT_LT(hit.part, 16 * 32 * 2);
  // The interpolated normal is close to the sphere's true normal at the hit point.
  const Vec3 p = Vec3(0.1, 0.2, -5) + hit.t * Vec3(0, 0, 1);
  EXPECT_GT(dot(hit.shading_normal, normalize(p)), 0.999);
  EXPECT_NEAR(length(hit.shading_normal), 1, 1e-12);
}

TEST(MeshTest, LargeMeshAgreesWithBruteForce) {
  const MeshData data = sphere_mesh(250, 200);  // 100,000 triangles
  const auto start = std::chrono::steady_clock::now();
  const Mesh mesh(data);
  snell::math::Pcg32 rng(3);
  int hits = 0;
  for (int i = 0; i < 200; ++i) {
    const Vec3 o = 3 * shape_checks::random_unit(rng);
    const Ray ray{o, 0.9 * shape_checks::random_unit(rng) - o, 0};
    LocalHit bvh_hit;
    const bool got = mesh.intersect(ray, 1e-9, kInfinity, bvh_hit);
    double best = kInfinity;
    for (const auto& f : data.faces) {
      TriangleHit th;
      if (intersect_triangle(data.vertices[f[0]], data.vertices[f[1]], data.vertices[f[2]], ray, 1e-9, best,
                             th))
        best = th.t;
    }
    ASSERT_EQ(got, best < kInfinity);
    if (got) {
      ++hits;
      EXPECT_DOUBLE_EQ(bvh_hit.t, best);
    }
  }
  EXPECT_GT(hits, 50);
  // 100k rays through the BVH must be far faster than brute force would be (1e10 tests).
  const auto t0 = std::chrono::steady_clock::now();
  for (int i = 0; i < 100000; ++i) {
    const Vec3 o = 3 * shape_checks::random_unit(rng);
    LocalHit h;
    mesh.intersect({o, shape_checks::random_unit(rng) - o, 0}, 1e-9, kInfinity, h);
  }
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_LT(secs, 5.0);
  std::printf("100k-triangle mesh: build+check %.2fs, 100k rays %.3fs\n",
              std::chrono::duration<double>(t0 - start).count(), secs);
}

// crosses (an any-hit walk in no particular order, for shadow rays) finds a crossing exactly when intersect
// does, over windows that end before, between and after a ray's crossings, from inside and outside.
TEST(MeshTest, CrossesAgreesWithIntersectOverAnyWindow) {
  const Mesh mesh(sphere_mesh(40, 30));
  snell::math::Pcg32 rng(11);
  int crossed = 0, missed = 0;
  for (int i = 0; i < 4000; ++i) {
    const Vec3 o = (i % 2 ? 0.5 : 3.0) * shape_checks::random_unit(rng);
    const Ray ray{o, shape_checks::random_unit(rng) * (0.5 + rng.next_double()), 0};
    const double t_min = i % 3 == 0 ? 1e-9 : 4 * rng.next_double();
    const double t_max = i % 5 == 0 ? kInfinity : t_min + 4 * rng.next_double();
    LocalHit hit;
    const bool expected = mesh.intersect(ray, t_min, t_max, hit);
    ASSERT_EQ(mesh.crosses(ray, t_min, t_max), expected) << "ray " << i;
    (expected ? crossed : missed) += 1;
  }
  EXPECT_GT(crossed, 500);
  EXPECT_GT(missed, 500);
}

TEST(MeshTest, RayThroughASharedEdgeReportsTheLowestNumberedFace) {
  // A flat 20 x 20 grid of squares cut into triangles, faces numbered in shuffled order; rays straight down
  // through edge midpoints and grid vertices meet two or more faces at t = 1 exactly. The face reported
  // must be brute force's lowest-numbered among those, whatever order the tree tests them in.
  constexpr int kN = 20;
  MeshData data;
  for (int j = 0; j <= kN; ++j)
    for (int i = 0; i <= kN; ++i) data.vertices.push_back({double(i), double(j), 0});
  for (int j = 0; j < kN; ++j)
    for (int i = 0; i < kN; ++i) {
      const int a = j * (kN + 1) + i, b = a + 1, c = a + kN + 1, d = c + 1;
      data.faces.push_back({a, b, d});
      data.faces.push_back({a, d, c});
    }
  snell::math::Pcg32 rng(11);
  for (size_t f = data.faces.size() - 1; f > 0; --f)
    std::swap(data.faces[f], data.faces[rng.next_uint() % (f + 1)]);
  const Mesh mesh(data);
  int ties = 0;
  for (int k = 0; k < 300; ++k) {
    const double x = 1 + rng.next_uint() % (2 * kN - 2) * 0.5, y = 1 + rng.next_uint() % (2 * kN - 2) * 0.5;
    const Ray ray{{x, y, 1}, {0, 0, -1}, 0};
    int lowest = -1, crossings = 0;
    for (int f = 0; f < static_cast<int>(data.faces.size()); ++f) {
      const auto& v = data.faces[f];
      TriangleHit th;
      if (!intersect_triangle(data.vertices[v[0]], data.vertices[v[1]], data.vertices[v[2]], ray, 1e-9,
                              kInfinity, th))
        continue;
      ASSERT_EQ(th.t, 1.0);
      ++crossings;
      if (lowest < 0) lowest = f;
    }
    ASSERT_GE(lowest, 0);
    ties += crossings > 1;
    LocalHit hit;
    ASSERT_TRUE(mesh.intersect(ray, 1e-9, kInfinity, hit));
    EXPECT_EQ(hit.part, lowest) << x << " " << y;
  }
  EXPECT_GT(ties, 200);
}

TEST(MeshTest, BadIndicesThrow) {
  MeshData data = cube_mesh();
  data.faces.push_back({0, 1, 8});
  EXPECT_THROW((Mesh(data)), std::invalid_argument);
  data = cube_mesh();
  data.normal_indices.push_back({0, 0, 0});  // not parallel to faces
  EXPECT_THROW((Mesh(data)), std::invalid_argument);
}

TEST(MeshTest, EmptyMeshHasNoHits) {
  const Mesh mesh(MeshData{});
  LocalHit hit;
  EXPECT_FALSE(mesh.intersect({{0, 0, 0}, {0, 0, 1}, 0}, 0, kInfinity, hit));
  EXPECT_TRUE(mesh.bounds().empty());
}
