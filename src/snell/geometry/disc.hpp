#pragma once
#include "snell/geometry/shape.hpp"

namespace snell::geometry {

/// POV-Ray `disc { center, normal, radius [, hole_radius] }`: flat, inside test as POV-Ray (below the plane).
class Disc final : public Shape {
 public:
  Disc(const Vec3& center, const Vec3& normal, double radius, double hole_radius);

  Bounds3 bounds() const override;
  bool intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const override;
  void all_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const override;
  bool inside(const Vec3& p) const override;
  std::string_view kind() const override { return "disc"; }

 private:
  Vec3 center_;
  Vec3 normal_;  // unit
  Vec3 u_, v_;   // in-plane frame for uv
  double radius_, hole_radius_;
};

}  // namespace snell::geometry
