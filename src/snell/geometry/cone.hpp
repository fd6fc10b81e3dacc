#pragma once
#include "snell/geometry/hit_buffer.hpp"
#include "snell/geometry/shape.hpp"

namespace snell::geometry {

/// POV-Ray `cone { base, base_radius, cap, cap_radius [open] }`.
class Cone final : public Shape {
 public:
  Cone(const Vec3& base, double base_radius, const Vec3& cap, double cap_radius, bool open);

  Bounds3 bounds() const override;
  bool intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const override;
  bool crosses(const Ray& ray, double t_min, double t_max) const override;
  void all_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const override;
  bool inside(const Vec3& p) const override;
  bool inside_within_bounds() const override { return true; }
  /// Translations and uniform scales: the axis keeps its direction, so the frame of uv does too.
  std::shared_ptr<const Shape> placed(const math::Transform& t) const override;
  std::string_view kind() const override { return "cone"; }

 private:
  /// Every crossing into `hits` (a HitBuffer<4>, a NearestBuffer for intersect, an AnyBuffer for crosses).
  template <typename Buffer>
  void gather(const Ray& ray, Buffer& hits) const;
  double radius_at(double z) const { return base_radius_ + slope_ * z; }

  Vec3 base_;
  Vec3 u_, v_, w_;  // orthonormal frame, w_ along the axis
  double length_;
  double base_radius_, cap_radius_;
  double slope_;  // d radius / d z
  bool open_;
};

}  // namespace snell::geometry
