#pragma once
#include <array>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include "snell/geometry/shape.hpp"
#include "snell/geometry/triangle_kernel.hpp"

namespace snell::geometry {

class TriangleTree;

/// Triangle soup with optional per-vertex normals and uvs, shared by POV-Ray `mesh`, `mesh2` and imported
/// meshes. Index triples refer into the vectors; `normal_indices`/`uv_indices` are empty or parallel to
/// `faces`. `texture_indices` (per face, -1 = the mesh's own texture) select from the object's texture list.
struct MeshData {
  std::vector<Vec3> vertices;
  std::vector<Vec3> normals;
  std::vector<Vec2> uvs;
  std::vector<std::array<int, 3>> faces;
  std::vector<std::array<int, 3>> normal_indices;
  std::vector<std::array<int, 3>> uv_indices;
  std::vector<int> texture_indices;
  /// POV-Ray `inside_vector`: with it, a closed mesh is a solid (inside test by ray parity).
  std::optional<Vec3> inside_vector;
};

/// POV-Ray `mesh`/`mesh2`: triangles under an internal BVH (triangle_tree.hpp: eight-wide, triangles packed
/// for SIMD tests in float, each hit found in double). Hits report the face index in `LocalHit::part`;
/// of faces hit at the very same t (a ray through a shared edge), the lowest-numbered. Without
/// `inside_vector` a mesh has no interior (POV-Ray: Inside is false). The BVH is built on the first query: a
/// mesh the Embree back end walks as native triangles (and only refines with `face_hit`) never needs it,
/// which saves its memory.
class Mesh final : public Shape {
 public:
  explicit Mesh(MeshData data);
  ~Mesh() override;

  Bounds3 bounds() const override;
  bool intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const override;
  /// Any face's crossing, found by a walk in no particular order that stops at the first.
  bool crosses(const Ray& ray, double t_min, double t_max) const override;
  void all_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const override;
  bool inside(const Vec3& p) const override;
  std::string_view kind() const override { return "mesh"; }

  const MeshData& data() const { return data_; }

  /// Where `ray` meets the plane of face `face` and its barycentric coordinates there, clamped to the
  /// triangle: how a float hit found by Embree is redone in double precision. nullopt for a ray parallel to
  /// the face or a non-finite t.
  struct FaceCrossing {
    double t, b1, b2;
  };
  std::optional<FaceCrossing> face_crossing(int face, const Ray& ray) const;
  /// The hit at a crossing of face `face`: its normals interpolated and uv. Built for the nearest crossing
  /// only (Embree's filter meets farther ones first, and shadow rays need none).
  LocalHit make_hit(int face, double t, double b1, double b2) const;

 private:
  bool crossing(int face, const Ray& ray, double t_min, double t_max, TriangleHit& hit) const;
  const std::array<int, 3>* normal_face(int face) const;
  const std::array<int, 3>* uv_face(int face) const;
  const TriangleTree& tree() const;

  MeshData data_;
  Bounds3 bounds_;
  mutable std::once_flag tree_built_;
  mutable std::unique_ptr<TriangleTree> tree_;
};

}  // namespace snell::geometry
