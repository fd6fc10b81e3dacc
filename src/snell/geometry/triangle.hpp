#pragma once
#include <array>

#include "snell/geometry/shape.hpp"
#include "snell/geometry/triangle_kernel.hpp"

namespace snell::geometry {

/// POV-Ray `triangle { a, b, c }` and, with vertex normals, `smooth_triangle { a, na, b, nb, c, nc }`.
class Triangle final : public Shape {
 public:
  Triangle(const Vec3& a, const Vec3& b, const Vec3& c);
  Triangle(const Vec3& a, const Vec3& na, const Vec3& b, const Vec3& nb, const Vec3& c, const Vec3& nc);

  Bounds3 bounds() const override;
  bool intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const override;
  void all_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const override;
  bool inside(const Vec3& p) const override;
  std::string_view kind() const override { return smooth_ ? "smooth_triangle" : "triangle"; }

  const std::array<Vec3, 3>& vertices() const { return v_; }
  /// The crossing intersect() reports, without its normals (accelerators test many triangles this way
  /// and complete only the nearest).
  bool crossing(const Ray& ray, double t_min, double t_max, TriangleHit& out) const {
    return intersect_triangle(v_[0], v_[1], v_[2], ray, t_min, t_max, out);
  }
  /// The hit intersect() reports for a crossing found by crossing() (so an accelerator that found it
  /// need not test the triangle again).
  LocalHit local_hit(const TriangleHit& crossing) const;
  /// local_hit of a triangle without vertex normals, from its vertices alone (an accelerator holding a
  /// copy of them need not read the shape).
  static LocalHit flat_hit(const std::array<Vec3, 3>& vertices, const TriangleHit& crossing);
  bool smooth() const { return smooth_; }

 private:
  std::array<Vec3, 3> v_;
  std::array<Vec3, 3> n_{};
  bool smooth_ = false;
};

}  // namespace snell::geometry
