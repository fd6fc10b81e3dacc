#pragma once
#include "snell/geometry/shape.hpp"

namespace snell::geometry {

/// POV-Ray `superellipsoid { <e, n> }` (POV-Ray 3.7 reference, "Superquadric Ellipsoid"): the solid
/// (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) <= 1 inside the box [-1, 1]^3; e shapes the x-y cross
/// sections, n the profile along z.
class Superellipsoid final : public Shape {
 public:
  Superellipsoid(double east_west, double north_south);

  Bounds3 bounds() const override { return {Vec3(-1), Vec3(1)}; }
  bool intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const override;
  void all_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const override;
  bool inside(const Vec3& p) const override { return gauge(p) < 1; }
  std::string_view kind() const override { return "superellipsoid"; }

  /// The body's gauge function F(p)^(n/2): positively homogeneous of degree one, so it is 1 on the
  /// surface, s at s times a surface point, and Lipschitz for sphere tracing.
  double gauge(const Vec3& p) const;
  /// Outward normal (not unit length) at a surface point.
  Vec3 normal(const Vec3& p) const;

 private:
  template <typename Sink>
  void trace(const Ray& ray, double t_min, double t_max, Sink&& sink) const;

  double e_, n_;
  /// max |grad gauge| over space: 1 / (distance from the centre to the nearest surface point).
  double lipschitz_;
};

}  // namespace snell::geometry
