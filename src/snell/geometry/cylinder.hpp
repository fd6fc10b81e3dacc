#pragma once
#include "snell/geometry/hit_buffer.hpp"
#include "snell/geometry/shape.hpp"

namespace snell::geometry {

/// POV-Ray `cylinder { base, cap, radius [open] }`.
class Cylinder final : public Shape {
 public:
  Cylinder(const Vec3& base, const Vec3& cap, double radius, bool open);

  Bounds3 bounds() const override;
  bool intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const override;
  bool crosses(const Ray& ray, double t_min, double t_max) const override;
  void all_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const override;
  bool inside(const Vec3& p) const override;
  bool inside_within_bounds() const override { return true; }
  /// Translations and uniform scales: the axis keeps its direction, so the frame of uv does too.
  std::shared_ptr<const Shape> placed(const math::Transform& t) const override;
  std::string_view kind() const override { return "cylinder"; }

 private:
  /// Every crossing into `hits` (a HitBuffer<4>, a NearestBuffer for intersect, an AnyBuffer for crosses).
  template <typename Buffer>
  void gather(const Ray& ray, Buffer& hits) const;

  Vec3 base_;
  Vec3 u_, v_, w_;  // orthonormal frame, w_ along the axis
  double length_;
  double radius_;
  bool open_;
};

}  // namespace snell::geometry
