#pragma once
// A box outside which a polynomial in x, y, z is provably positive, so that a `poly`, `cubic` or
// `quartic` (the solid where the polynomial is negative) whose surface is bounded gets a bounding box:
// POV-Ray gives these shapes none, and an unbounded shape is tested by every ray of the scene.
#include <optional>
#include <span>

#include "snell/math/bounds.hpp"

namespace snell::geometry {

/// One term c x^i y^j z^k.
struct PolyTerm {
  int i, j, k;
  double c;
};

/// Exponents up to kMaxPolynomialDegree. A box holding every point where the sum of `terms` is zero or
/// negative, or nullopt when that cannot be shown (the surface may be unbounded, as every cubic's is). Two
/// steps: a weighted AM-GM bound gives a first box when each variable has a pure even power of positive
/// coefficient that dominates every other term; interval arithmetic on a subdivision of that box then keeps
/// only the cells where the sum may reach zero.
std::optional<math::Bounds3> poly_negative_region_bounds(std::span<const PolyTerm> terms);

}  // namespace snell::geometry
