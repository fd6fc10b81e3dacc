#include "snell/geometry/mesh.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "snell/geometry/triangle_kernel.hpp"
#include "snell/geometry/triangle_tree.hpp"

namespace snell::geometry {
namespace {

void check_indices(const std::vector<std::array<int, 3>>& faces, size_t count, const char* what) {
  for (size_t f = 0; f < faces.size(); ++f) {
    for (int i : faces[f]) {
      if (i < 0 || static_cast<size_t>(i) >= count)
        throw std::invalid_argument("mesh: face " + std::to_string(f) + " has " + what + " index " +
                                    std::to_string(i) + " out of range (" + std::to_string(count) +
                                    " given)");
    }
  }
}

}  // namespace

Mesh::Mesh(MeshData data) : data_(std::move(data)) {
  for (const Vec3& v : data_.vertices)
    if (!is_finite(v)) throw std::invalid_argument("mesh: vertices must be finite");
  check_indices(data_.faces, data_.vertices.size(), "vertex");
  const auto check_parallel = [&](const std::vector<std::array<int, 3>>& idx, size_t count,
                                  const char* what) {
    if (idx.empty()) return;
    if (idx.size() != data_.faces.size())
      throw std::invalid_argument(std::string("mesh: ") + what + " index list must match the face count");
    check_indices(idx, count, what);
  };
  check_parallel(data_.normal_indices, data_.normals.size(), "normal");
  check_parallel(data_.uv_indices, data_.uvs.size(), "uv");
  if (data_.inside_vector && length_squared(*data_.inside_vector) == 0)
    throw std::invalid_argument("mesh: inside_vector must not be zero");

  for (const auto& face : data_.faces)
    for (int i : face) bounds_.unite(data_.vertices[i]);
}

Mesh::~Mesh() = default;

Bounds3 Mesh::bounds() const {
  return bounds_;
}

const TriangleTree& Mesh::tree() const {
  std::call_once(tree_built_,
                 [this] { tree_ = std::make_unique<TriangleTree>(data_.vertices, data_.faces); });
  return *tree_;
}

// Moeller and Trumbore 1997 without the edge tests: t and the barycentrics of the ray's crossing with the
// face's plane.
std::optional<Mesh::FaceCrossing> Mesh::face_crossing(int face, const Ray& ray) const {
  const auto& f = data_.faces[face];
  const Vec3 &a = data_.vertices[f[0]], &b = data_.vertices[f[1]], &c = data_.vertices[f[2]];
  const Vec3 e1 = b - a, e2 = c - a;
  const Vec3 p = cross(ray.direction, e2);
  const double det = dot(e1, p);
  if (!(std::abs(det) > 0)) return std::nullopt;
  const Vec3 s = ray.origin - a;
  const Vec3 q = cross(s, e1);
  const double t = dot(e2, q) / det;
  double b1 = std::clamp(dot(s, p) / det, 0.0, 1.0);
  double b2 = std::clamp(dot(ray.direction, q) / det, 0.0, 1.0);
  if (b1 + b2 > 1) {
    const double sum = b1 + b2;
    b1 /= sum;
    b2 /= sum;
  }
  if (!std::isfinite(t)) return std::nullopt;
  return FaceCrossing{t, b1, b2};
}

// mesh2 without normal_indices/uv_indices uses the face indices when the lists are per vertex (POV-Ray
// documentation, "Mesh2").
const std::array<int, 3>* Mesh::normal_face(int face) const {
  if (!data_.normal_indices.empty()) return &data_.normal_indices[face];
  if (!data_.normals.empty() && data_.normals.size() == data_.vertices.size()) return &data_.faces[face];
  return nullptr;
}

const std::array<int, 3>* Mesh::uv_face(int face) const {
  if (!data_.uv_indices.empty()) return &data_.uv_indices[face];
  if (!data_.uvs.empty() && data_.uvs.size() == data_.vertices.size()) return &data_.faces[face];
  return nullptr;
}

LocalHit Mesh::make_hit(int face, double t, double b1, double b2) const {
  const auto& f = data_.faces[face];
  const Vec3 &a = data_.vertices[f[0]], &b = data_.vertices[f[1]], &c = data_.vertices[f[2]];
  LocalHit hit;
  hit.t = t;
  hit.part = face;
  hit.normal = normalize(cross(b - a, c - a));
  const double b0 = 1 - b1 - b2;
  if (const auto* nf = normal_face(face)) {
    const Vec3 n = b0 * data_.normals[(*nf)[0]] + b1 * data_.normals[(*nf)[1]] + b2 * data_.normals[(*nf)[2]];
    if (length_squared(n) > 0) hit.shading_normal = normalize(n);
  }
  if (const auto* uf = uv_face(face)) {
    const Vec2 &u0 = data_.uvs[(*uf)[0]], &u1 = data_.uvs[(*uf)[1]], &u2 = data_.uvs[(*uf)[2]];
    hit.uv = {b0 * u0.u + b1 * u1.u + b2 * u2.u, b0 * u0.v + b1 * u1.v + b2 * u2.v};
  } else {
    hit.uv = {b1, b2};
  }
  return hit;
}

bool Mesh::crossing(int face, const Ray& ray, double t_min, double t_max, TriangleHit& hit) const {
  const auto& f = data_.faces[face];
  return intersect_triangle(data_.vertices[f[0]], data_.vertices[f[1]], data_.vertices[f[2]], ray, t_min,
                            t_max, hit);
}

bool Mesh::intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const {
  int best = -1;
  TriangleHit best_hit{};
  math::lanes::with_lanes([&]<int L>() __attribute__((always_inline)) {
    tree().walk<L>(ray, t_min, t_max, [&](uint32_t id, double& t_limit) {
      const int face = static_cast<int>(id);
      // A lower-numbered face hit at the same t as the best so far replaces it: the answer does not
      // depend on the order of the walk.
      const double limit = best >= 0 && face < best ? std::nextafter(t_limit, math::kInfinity) : t_limit;
      TriangleHit th;
      if (!crossing(face, ray, t_min, limit, th)) return;
      t_limit = th.t;
      best = face;
      best_hit = th;
    });
  });
  if (best < 0) return false;
  hit = make_hit(best, best_hit.t, best_hit.b1, best_hit.b2);
  return true;
}

bool Mesh::crosses(const Ray& ray, double t_min, double t_max) const {
  bool crossed = false;
  math::lanes::with_lanes([&]<int L>() __attribute__((always_inline)) {
    crossed = tree().walk<L, false, true>(ray, t_min, t_max, [&](uint32_t face, double&) {
      TriangleHit th;
      return crossing(static_cast<int>(face), ray, t_min, t_max, th);
    });
  });
  return crossed;
}

void Mesh::all_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const {
  const size_t first = hits.size();
  math::lanes::with_lanes([&]<int L>() __attribute__((always_inline)) {
    tree().walk<L>(ray, t_min, t_max, [&](uint32_t face, double&) {
      TriangleHit th;
      if (crossing(static_cast<int>(face), ray, t_min, t_max, th))
        hits.push_back(make_hit(static_cast<int>(face), th.t, th.b1, th.b2));
    });
  });
  std::sort(
      hits.begin() + static_cast<std::ptrdiff_t>(first), hits.end(),
      [](const LocalHit& a, const LocalHit& b) { return a.t < b.t || (a.t == b.t && a.part < b.part); });
}

// POV-Ray (mesh.cpp, Mesh::Inside): with inside_vector, a point is inside when a ray from it along that
// vector crosses the mesh an odd number of times; without it a mesh has no inside.
bool Mesh::inside(const Vec3& p) const {
  if (!data_.inside_vector) return false;
  const Ray ray{p, *data_.inside_vector, 0};
  int crossings = 0;
  math::lanes::with_lanes([&]<int L>() __attribute__((always_inline)) {
    tree().walk<L>(ray, 0.0, math::kInfinity, [&](uint32_t face, double&) {
      TriangleHit th;
      if (crossing(static_cast<int>(face), ray, 0.0, math::kInfinity, th)) ++crossings;
    });
  });
  return crossings % 2 == 1;
}

}  // namespace snell::geometry
