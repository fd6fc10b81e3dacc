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
  bool crosses(const Ray& ray, double t_min, double t_max) const override;
  void all_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const override;
  bool span(const Ray& ray, double& t_entry, double& t_exit) const override;
  bool inside(const Vec3& p) const override;
  bool inside_within_bounds() const override { return true; }
  /// Translations and positive scales along the axes: uv (positions across each face) do not change.
  std::shared_ptr<const Shape> placed(const math::Transform& t) const override;
  std::string_view kind() const override { return "box"; }

  const Vec3& lo() const { return lo_; }
  const Vec3& hi() const { return hi_; }
  /// The slab method's entry and exit parameters (t0 <= t1) and the axes of their faces; false on a miss.
  /// all_hits reports t0, then t1 where it differs, each with slab_hit (CSG of boxes reads them so).
  bool slabs(const Ray& ray, double& t0, double& t1, int& axis0, int& axis1) const;
  /// The crossing at `t` through the face across `axis` that slabs found, entering or `leaving`.
  LocalHit slab_hit(const Ray& ray, double t, int axis, bool leaving) const;

 private:
  /// The crossing at `t` through the face across `axis` whose outward normal is `sign` along it.
  LocalHit face_hit(const Ray& ray, double t, int axis, double sign) const;
  /// Every crossing into `hits` (a HitBuffer<2>, or a NearestBuffer for intersect).
  template <typename Buffer>
  void gather(const Ray& ray, Buffer& hits) const;

  Vec3 lo_, hi_;
};

}  // namespace snell::geometry
