#pragma once
// POV-Ray `poly`, `cubic` and `quartic`: the solid where a polynomial in x, y, z is negative. Along a ray
// the polynomial becomes one in t, whose roots the Sturm solver finds (so `sturm` is always on). Unlike
// POV-Ray's, a poly whose surface is provably bounded gets a bounding box (poly_bounds.hpp), so that only
// the rays that reach it test it.
#include <vector>

#include "snell/geometry/poly_bounds.hpp"
#include "snell/geometry/shape.hpp"

namespace snell::geometry {

/// Highest order `Poly` accepts: the root solver's degree limit.
int max_poly_order();

/// Number of coefficients of a poly of this order: (n+1)(n+2)(n+3)/6.
int poly_coefficient_count(int order);

class Poly final : public Shape {
 public:
  /// `coefficients` in POV-Ray's order: terms x^i y^j z^k by falling i, then falling j, then falling k,
  /// with i + j + k <= order (reference, "Poly, Cubic and Quartic").
  Poly(int order, const std::vector<double>& coefficients);

  /// A box when the surface is provably bounded (poly_negative_region_bounds), else infinite.
  Bounds3 bounds() const override { return bounds_; }
  bool intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const override;
  void all_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const override;
  bool inside(const Vec3& p) const override;
  bool inside_within_bounds() const override { return bounded_; }
  std::string_view kind() const override { return "poly"; }

  double value(const Vec3& p) const;
  Vec3 gradient(const Vec3& p) const;

 private:
  using Term = PolyTerm;
  /// Roots along the ray in increasing t; returns their number.
  int roots_along(const Ray& ray, double t_min, double t_max, double* ts) const;

  int order_;
  std::vector<Term> terms_;
  Bounds3 bounds_ = Bounds3::infinite();
  bool bounded_ = false;
};

}  // namespace snell::geometry
