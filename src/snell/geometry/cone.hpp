#pragma once
#include "snell/geometry/shape.hpp"

namespace snell::geometry {

/// POV-Ray `cone { base, base_radius, cap, cap_radius [open] }`.
class Cone final : public Shape {
 public:
  Cone(const Vec3& base, double base_radius, const Vec3& cap, double cap_radius, bool open);

  Bounds3 bounds() const override;
  bool intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const override;
  void all_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const override;
  bool inside(const Vec3& p) const override;
  std::string_view kind() const override { return "cone"; }

 private:
};

}  // namespace snell::geometry
