#pragma once
#include "snell/geometry/hit_buffer.hpp"
#include "snell/geometry/shape.hpp"

namespace snell::geometry {

/// POV-Ray `box { corner1, corner2 }`.
class Box final : public Shape {
 public:
  Box(const Vec3& corner1, const Vec3& corner2);

  Bounds3 bounds() const override;
  bool intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const override;
  void all_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const override;
  bool inside(const Vec3& p) const override;
  bool inside_within_bounds() const override { return true; }
  std::string_view kind() const override { return "box"; }

 private:
  void gather(const Ray& ray, HitBuffer<2>& hits) const;

  Vec3 lo_, hi_;
};

}  // namespace snell::geometry
