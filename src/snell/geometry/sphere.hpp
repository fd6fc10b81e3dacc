#pragma once
#include "snell/geometry/shape.hpp"

namespace snell::geometry {

/// POV-Ray `sphere { center, radius }`.
class Sphere final : public Shape {
 public:
  Sphere(const Vec3& center, double radius) : center_(center), radius_(radius) {}

  Bounds3 bounds() const override;
  bool intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const override;
  bool crosses(const Ray& ray, double t_min, double t_max) const override;
  void all_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const override;
  bool span(const Ray& ray, double& t_entry, double& t_exit) const override;
  bool inside(const Vec3& p) const override;
  bool inside_within_bounds() const override { return true; }
  /// Translations and uniform scales: uv (directions from the centre) do not change.
  std::shared_ptr<const Shape> placed(const math::Transform& t) const override;
  std::string_view kind() const override { return "sphere"; }

  const Vec3& center() const { return center_; }
  double radius() const { return radius_; }

 private:
  /// Both roots of |o + t d - c|^2 = r^2, t0 <= t1; false when the ray misses.
  bool roots(const Ray& ray, double& t0, double& t1) const;
  /// The nearest root in (t_min, t_max); false when there is none.
  bool nearest_root(const Ray& ray, double t_min, double t_max, double& t) const;
  LocalHit make_hit(const Ray& ray, double t) const;

  Vec3 center_;
  double radius_;
};

}  // namespace snell::geometry
