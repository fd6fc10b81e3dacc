#pragma once
#include "snell/geometry/shape.hpp"

namespace snell::geometry {

/// POV-Ray `quadric { <A,B,C>, <D,E,F>, <G,H,I>, J }`, the surface
///   A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x + H y + I z + J = 0
/// (POV-Ray 3.7 reference, "Quadric"). Inside is where the left side is negative; the normal is its
/// gradient. Unbounded unless the quadratic part is definite with a bounded inside (an ellipsoid).
class Quadric final : public Shape {
 public:
  Quadric(const Vec3& squares, const Vec3& mixed, const Vec3& linear, double constant);

  Bounds3 bounds() const override { return bounds_; }
  /// For a quadric without mixed terms, the box of its inside within `box` by interval arithmetic
  /// (quadric_bounds.cpp): an infinite cylinder or a hyperboloid cut by planes gets finite bounds.
  Bounds3 inside_bounds_within(const Bounds3& box) const override;
  bool intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const override;
  void all_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const override;
  bool inside(const Vec3& p) const override { return value(p) < 0; }
  std::string_view kind() const override { return "quadric"; }

  /// The left side of the equation at `p`.
  double value(const Vec3& p) const;
  Vec3 gradient(const Vec3& p) const;

 private:
  /// The crossings in increasing t (0, 1 or 2); returns their count.
  int roots(const Ray& ray, double t[2]) const;
  Bounds3 compute_bounds() const;

  Vec3 sq_;   // A, B, C
  Vec3 mix_;  // D (xy), E (xz), F (yz)
  Vec3 lin_;  // G, H, I
  double j_;
  Bounds3 bounds_;
};

}  // namespace snell::geometry
