#pragma once
// Real roots of low-degree polynomials inside an interval, for shapes whose ray equation is a polynomial
// in t (torus, blob, quartic/poly, lathe, sor, prism). A Bernstein-form sign test first drops windows
// without roots; roots are then isolated by the roots of the derivatives (p is monotonic between them) and
// refined by bracketed Newton iteration; critical points where p vanishes are the roots of even
// multiplicity. See polynomial.cpp for the references.
#include <array>
#include <cmath>
#include <span>
#include <utility>

namespace snell::geometry {

/// Highest degree `real_roots` accepts.
inline constexpr int kMaxPolynomialDegree = 6;

/// Writes the distinct real roots of sum_i coeffs[i] * x^i (coefficients in ASCENDING order) that lie in
/// (lo, hi] into `roots`, in increasing order, and returns their number. Leading coefficients that are
/// negligible relative to the others lower the degree. A polynomial that vanishes identically has no
/// isolated roots and yields 0. Throws std::invalid_argument for a degree above kMaxPolynomialDegree, a
/// non-finite or empty interval, or `roots` shorter than the degree. With `max_roots`, only the smallest
/// max_roots roots are refined and written (a nearest-hit query needs one: the others cost their isolation
/// and Newton refinement).
int real_roots(std::span<const double> coeffs, double lo, double hi, std::span<double> roots,
               int max_roots = kMaxPolynomialDegree);

/// Whether real_roots(coeffs, lo, hi, ...) would find a root, without refining any: a shadow ray needs only
/// that. An empty interval has none; otherwise the same conditions as real_roots.
bool has_root(std::span<const double> coeffs, double lo, double hi);

/// Evaluates sum_i coeffs[i] * x^i (Horner).
double evaluate_polynomial(std::span<const double> coeffs, double x);

/// Stable roots of a x^2 + b x + c = 0 (no interval), t0 <= t1; false when there is no real root. A
/// vanishing `a` degrades to the linear root (then t0 == t1). Inline: every quadric and cylinder test
/// calls it, most of them to learn that the ray misses (1.9% of benchmark.pov's profile as a call).
inline bool solve_quadratic(double a, double b, double c, double& t0, double& t1) {
  if (a == 0) {
    if (b == 0) return false;
    t0 = t1 = -c / b;
    return true;
  }
  const double disc = b * b - 4 * a * c;
  if (disc < 0) return false;
  // Avoid cancellation (Numerical Recipes 5.6): q = -(b + sign(b) sqrt(disc)) / 2.
  const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
  if (q == 0) {
    t0 = t1 = 0;
    return true;
  }
  t0 = q / a;
  t1 = c / q;
  if (t0 > t1) std::swap(t0, t1);
  return true;
}

}  // namespace snell::geometry
