#include "snell/geometry/polynomial.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace snell::geometry {
namespace {

// Coefficients below this fraction of the largest one count as zero (degree reduction, Sturm remainders).
constexpr double kRelativeZero = 1e-13;

struct Poly {
  std::array<double, kMaxPolynomialDegree + 1> c{};
  int degree = -1;  // -1: the zero polynomial

  double operator()(double x) const {
    double r = 0;
    for (int i = degree; i >= 0; --i) r = r * x + c[i];
    return r;
  }
  double max_abs() const {
    double m = 0;
    for (int i = 0; i <= degree; ++i) m = std::max(m, std::fabs(c[i]));
    return m;
  }
  // Drops leading coefficients that are negligible against `scale`.
  void trim(double scale) {
    while (degree >= 0 && std::fabs(c[degree]) <= kRelativeZero * scale) c[degree--] = 0;
  }
};

Poly derivative(const Poly& p) {
  Poly d;
  d.degree = p.degree - 1;
  for (int i = 1; i <= p.degree; ++i) d.c[i - 1] = i * p.c[i];
  return d;
}

// Relative accuracy of the roots returned, and of the derivatives' roots that only split intervals: at a
// critical point found to 1e-10, a touching root's value is off by p'' 1e-20 x^2, below rounding.
constexpr double kRootAccuracy = 4e-16;
constexpr double kCriticalAccuracy = 1e-10;

double tolerance(double a, double b) {
  return 4e-16 * std::max({1.0, std::fabs(a), std::fabs(b)});
}

/// A bound on the rounding error of evaluating p at x by Horner's rule: 2 n u sum |c_i| |x|^i (Higham,
/// "Accuracy and Stability of Numerical Algorithms", 2002, eq. 5.3, with a factor 2 of margin).
double evaluation_error(const Poly& p, double x) {
  const double ax = std::fabs(x);
  double r = 0;
  for (int i = p.degree; i >= 0; --i) r = r * ax + std::fabs(p.c[i]);
  return 4.0 * p.degree * std::numeric_limits<double>::epsilon() * r;
}

/// p(x) and p'(x) in one Horner pass.
std::pair<double, double> value_and_slope(const Poly& p, double x) {
  double v = p.c[p.degree], d = 0;
  for (int i = p.degree - 1; i >= 0; --i) {
    d = d * x + v;
    v = v * x + p.c[i];
  }
  return {v, d};
}

/// Safeguarded Newton on [a, b], where p changes sign (p(a) = fa, p(b) = fb) at its one root there, to a
/// relative accuracy `accuracy` (the roots of derivatives only split intervals and need less).
double refine_bracketed(const Poly& p, double a, double b, double fa, double fb, double accuracy,
                        double start = std::numeric_limits<double>::quiet_NaN()) {
  // The secant through the ends starts nearer the root than the midpoint, and replaces a Newton step
  // that leaves the bracket (near a flat end); the Illinois rule halves the value kept at an end that
  // stays put twice, so the secant steps cannot stall on one side.
  int kept_side = 0;  // -1: a moved last time, +1: b moved
  auto secant = [&] {
    const double x = a - fa * (b - a) / (fb - fa);
    return x > a && x < b ? x : 0.5 * (a + b);
  };
  double x = start > a && start < b ? start : secant();
  for (int it = 0; it < 100; ++it) {
    if (b - a <= accuracy * std::max({1.0, std::fabs(a), std::fabs(b)})) break;
    const auto [f, df] = value_and_slope(p, x);
    if (f == 0) return x;
    if ((f > 0) == (fa > 0)) {
      a = x;
      fa = f;
      if (kept_side == -1) fb *= 0.5;
      kept_side = -1;
    } else {
      b = x;
      fb = f;
      if (kept_side == 1) fa *= 0.5;
      kept_side = 1;
    }
    double next = df != 0 ? x - f / df : a - 1;
    if (!(next > a && next < b)) next = secant();
    if (std::fabs(next - x) <= accuracy * std::max(1.0, std::fabs(x))) return next;
    x = next;
  }
  return x;
}

using RatioTable = std::array<std::array<double, kMaxPolynomialDegree + 1>, kMaxPolynomialDegree + 1>;

/// kBernsteinRatios[n][k][i] = C(k, i) / C(n, i): power to Bernstein basis of degree n.
constexpr std::array<RatioTable, kMaxPolynomialDegree + 1> kBernsteinRatios = [] {
  RatioTable binomial{};
  for (int a = 0; a <= kMaxPolynomialDegree; ++a) {
    binomial[a][0] = 1;
    for (int b = 1; b <= a; ++b)
      binomial[a][b] = binomial[a - 1][b - 1] + (b <= a - 1 ? binomial[a - 1][b] : 0);
  }
  std::array<RatioTable, kMaxPolynomialDegree + 1> ratios{};
  for (int n = 0; n <= kMaxPolynomialDegree; ++n)
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i <= k; ++i) ratios[n][k][i] = binomial[k][i] / binomial[n][i];
  return ratios;
}();

/// The sign changes of p's Bernstein coefficients on [lo, hi], which bound its roots there and match
/// their count's parity (Descartes' rule in Bernstein form): 0 proves p keeps its strict sign all over
/// [lo, hi] (the coefficients' convex hull holds the graph: Farouki and Rajan, "On the numerical condition
/// of polynomials in Bernstein form", 1987), 1 that exactly one simple root lies inside. Most calls from
/// the spline shapes have no root in the segment's window, and many one, settled without isolating. -1:
/// undecided, when a coefficient lies within 1e-9 of the largest of zero, a margin far above the rounding
/// of the change of basis on such windows.
/// With one change, `crossing` (when given) receives where the control polygon crosses zero: a start
/// near the root, as Bezier clipping's (Sederberg and Nishita, 1990).
int bernstein_sign_changes(const Poly& p, double lo, double hi, double* crossing = nullptr) {
  const int n = p.degree;
  // q(t) = p(lo + (hi - lo) t): Taylor shift to lo (repeated synthetic division), then scale.
  std::array<double, kMaxPolynomialDegree + 1> q = p.c;
  for (int k = 0; k < n; ++k)
    for (int i = n - 1; i >= k; --i) q[i] += lo * q[i + 1];
  const double width = hi - lo;
  double power = 1;
  for (int i = 0; i <= n; ++i, power *= width) q[i] *= power;
  // Bernstein coefficients b_k = sum_{i <= k} C(k, i) / C(n, i) q_i, the ratios tabulated per degree.
  const auto& ratio = kBernsteinRatios[static_cast<size_t>(n)];
  std::array<double, kMaxPolynomialDegree + 1> b{};
  double largest = 0;
  for (int k = 0; k <= n; ++k) {
    for (int i = 0; i <= k; ++i) b[k] += ratio[k][i] * q[i];
    largest = std::max(largest, std::fabs(b[k]));
  }
  const double margin = 1e-9 * largest;
  int changes = 0, last = 0;
  for (int k = 0; k <= n; ++k) {
    if (!(std::fabs(b[k]) > margin)) return -1;
    if (k > 0 && (b[k] > 0) != (b[k - 1] > 0)) {
      ++changes;
      last = k;
    }
  }
  if (changes == 1 && crossing) {
    const double t = (last - 1 + b[last - 1] / (b[last - 1] - b[last])) / n;
    *crossing = lo + width * t;
  }
  return changes;
}

/// Isolation by derivatives (C. Yuksel, "High-Performance Polynomial Root Finding for Graphics", HPG 2022):
/// the distinct roots of p' cut [lo, hi] into pieces on which p is monotonic, so each piece holds at most one
/// root, refined by Newton where p changes sign over it. A critical point where p vanishes within its
/// rounding error is a root of even multiplicity (p touches zero: a ray grazing a surface). Writes the roots
/// in [lo, hi] in increasing order, skipping `lo` itself when `open_lo`, and stops after `limit`.
/// On the polynomials that lathe2, sor1, prism1 and torus1 of POV-Ray's examples solve (recorded calls,
/// replayed): 1.2x, 1.75x, 1.9x and 1.35x faster than the Sturm sequences this replaced, same roots to 1e-12.
/// With `locate` false, stops at the first root found and writes a point of its bracket instead of
/// refining it (has_root).
int isolate(const Poly& p, double lo, double hi, bool open_lo, int limit, double accuracy, double* out,
            bool locate = true) {
  int n = 0;
  auto add = [&](double r) {
    if (n >= limit || (open_lo && r <= lo) || r < lo || r > hi) return;
    if (n > 0 && r - out[n - 1] <= 1e3 * tolerance(r, out[n - 1])) return;  // a cluster, reported once
    out[n++] = r;
  };
  if (p.degree == 1) {
    add(-p.c[0] / p.c[1]);
    return n;
  }
  if (p.degree == 2) {
    double t0, t1;
    if (solve_quadratic(p.c[2], p.c[1], p.c[0], t0, t1)) {
      add(t0);
      add(t1);
    }
    return n;
  }
  const Poly dp = derivative(p);
  std::array<double, kMaxPolynomialDegree + 1> points{};
  points[0] = lo;
  // (sign changes tested here too measured slower: the derivatives of a polynomial with roots mostly have
  // them.)
  const int critical = isolate(dp, lo, hi, false, kMaxPolynomialDegree, kCriticalAccuracy, points.data() + 1);
  const int count = critical + 2;
  points[static_cast<size_t>(count - 1)] = hi;
  std::array<double, kMaxPolynomialDegree + 1> values{};
  for (int i = 0; i < count; ++i) {
    values[i] = p(points[i]);
    const bool interior = i > 0 && i < count - 1;
    if (interior && std::fabs(values[i]) <= evaluation_error(p, points[i])) values[i] = 0;
  }
  for (int i = 0; i < count && n < limit; ++i) {
    if (values[i] == 0) add(points[i]);
    if (i + 1 < count && values[i] != 0 && values[i + 1] != 0 && (values[i] > 0) != (values[i + 1] > 0)) {
      if (!locate) {
        out[n++] = 0.5 * (points[i] + points[i + 1]);
        return n;
      }
      add(refine_bracketed(p, points[i], points[i + 1], values[i], values[i + 1], accuracy));
    }
  }
  return n;
}

}  // namespace

double evaluate_polynomial(std::span<const double> coeffs, double x) {
  double r = 0;
  for (size_t i = coeffs.size(); i-- > 0;) r = r * x + coeffs[i];
  return r;
}

namespace {

// A monic quadratic in closed form: the calls from spline shapes (prism, lathe, sor) are about half
// quadratics, for which the Sturm sequence and Newton refinement cost several times the formula.
int quadratic_roots(const Poly& p, double lo, double hi, std::span<double> roots, int max_roots) {
  double t0, t1;
  if (!solve_quadratic(1.0, p.c[1], p.c[0], t0, t1)) return 0;
  int n = 0;
  if (t0 > lo && t0 <= hi && max_roots > 0) roots[n++] = t0;
  if (t1 != t0 && t1 > lo && t1 <= hi && n < max_roots) roots[n++] = t1;
  return n;
}

/// The roots in (lo, hi] of a monic polynomial of degree 1 or 2, by formula.
int closed_form_roots(const Poly& p, double lo, double hi, std::span<double> roots, int max_roots) {
  if (p.degree == 2) return quadratic_roots(p, lo, hi, roots, max_roots);
  const double r = -p.c[0];
  if (!(r > lo && r <= hi && max_roots > 0)) return 0;
  roots[0] = r;
  return 1;
}

/// The polynomial with negligible leading coefficients dropped, divided by its leading coefficient
/// (monic scaling keeps every polynomial of the isolation on one scale); degree <= 0 when it has no
/// isolated roots (also for a non-finite coefficient).
Poly monic(std::span<const double> coeffs, double lo, double hi) {
  if (coeffs.size() > static_cast<size_t>(kMaxPolynomialDegree + 1))
    throw std::invalid_argument("real_roots: degree above " + std::to_string(kMaxPolynomialDegree));
  if (!std::isfinite(lo) || !std::isfinite(hi) || !(lo < hi))
    throw std::invalid_argument("real_roots: the interval must be finite and non-empty");
  Poly p;
  p.degree = static_cast<int>(coeffs.size()) - 1;
  for (int i = 0; i <= p.degree; ++i) {
    if (!std::isfinite(coeffs[i])) {
      p.degree = -1;
      return p;
    }
    p.c[i] = coeffs[i];
  }
  p.trim(p.max_abs());
  if (p.degree <= 0) return p;
  const double lead = p.c[p.degree];
  for (int i = 0; i <= p.degree; ++i) p.c[i] /= lead;
  return p;
}

}  // namespace

int real_roots(std::span<const double> coeffs, double lo, double hi, std::span<double> roots, int max_roots) {
  const Poly p = monic(coeffs, lo, hi);
  if (p.degree <= 0) return 0;
  if (roots.size() < static_cast<size_t>(p.degree))
    throw std::invalid_argument("real_roots: output span shorter than the degree");
  if (p.degree <= 2) return closed_form_roots(p, lo, hi, roots, max_roots);
  double crossing = 0;
  const int changes = bernstein_sign_changes(p, lo, hi, &crossing);
  if (changes == 0 || max_roots <= 0) return 0;
  if (changes == 1) {
    // The one root inside, bracketed by the ends (their signs differ beyond the margin).
    const double at_lo = p(lo), at_hi = p(hi);
    if ((at_lo > 0) != (at_hi > 0) && at_lo != 0 && at_hi != 0) {
      roots[0] = refine_bracketed(p, lo, hi, at_lo, at_hi, kRootAccuracy, crossing);
      return roots[0] > lo && roots[0] <= hi ? 1 : 0;
    }
  }
  return isolate(p, lo, hi, true, std::min(max_roots, static_cast<int>(roots.size())), kRootAccuracy,
                 roots.data());
}

bool has_root(std::span<const double> coeffs, double lo, double hi) {
  if (!(lo < hi)) return false;
  const Poly p = monic(coeffs, lo, hi);
  if (p.degree <= 0) return false;
  if (p.degree <= 2) {
    double roots[2];
    return closed_form_roots(p, lo, hi, roots, 1) > 0;
  }
  // Opposite signs at the ends: a root between them, wherever it is (most shadow rays that are blocked).
  const double at_lo = p(lo), at_hi = p(hi);
  if ((at_lo < 0 && at_hi > 0) || (at_lo > 0 && at_hi < 0)) return true;
  if (bernstein_sign_changes(p, lo, hi) == 0) return false;
  double root;
  return isolate(p, lo, hi, true, 1, kRootAccuracy, &root, false) > 0;
}

}  // namespace snell::geometry
