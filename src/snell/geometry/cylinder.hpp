#pragma once
#include "snell/geometry/shape.hpp"

namespace snell::geometry {

/// POV-Ray `cylinder { base, cap, radius [open] }`.
class Cylinder final : public Shape {
 public:
  Cylinder(const Vec3& base, const Vec3& cap, double radius, bool open);

  Bounds3 bounds() const override;
  bool intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const override;
  void all_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const override;
  bool inside(const Vec3& p) const override;
  std::string_view kind() const override { return "cylinder"; }

 private:
};

}  // namespace snell::geometry
