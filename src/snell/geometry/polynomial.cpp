#include "snell/geometry/polynomial.hpp"

#include <algorithm>
#include <cmath>
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

// Negated remainder of a / b (the next Sturm polynomial).
Poly negated_remainder(Poly a, const Poly& b) {
  const double scale = a.max_abs();
  for (int k = a.degree - b.degree; k >= 0; --k) {
    const double q = a.c[k + b.degree] / b.c[b.degree];
    for (int i = 0; i <= b.degree; ++i) a.c[k + i] -= q * b.c[i];
    a.c[k + b.degree] = 0;
  }
  a.degree = b.degree - 1;
  a.trim(scale);
  for (int i = 0; i <= a.degree; ++i) a.c[i] = -a.c[i];
  return a;
}

class SturmSequence {
 public:
  explicit SturmSequence(const Poly& p) {
    seq_[0] = p;
    seq_[1] = derivative(p);
    size_ = 2;
    while (size_ <= kMaxPolynomialDegree && seq_[size_ - 1].degree > 0) {
      Poly r = negated_remainder(seq_[size_ - 2], seq_[size_ - 1]);
      if (r.degree < 0) break;  // exact division: the last one is gcd(p, p')
      seq_[size_++] = r;
    }
  }

  int sign_changes(double x) const {
    int changes = 0;
    double last = 0;
    for (int i = 0; i < size_; ++i) {
      const double v = seq_[i](x);
      if (v == 0) continue;
      if (last != 0 && (v > 0) != (last > 0)) ++changes;
      last = v;
    }
    return changes;
  }

  const Poly& p() const { return seq_[0]; }
  const Poly& dp() const { return seq_[1]; }

 private:
  std::array<Poly, kMaxPolynomialDegree + 2> seq_;
  int size_ = 0;
};

double tolerance(double a, double b) {
  return 4e-16 * std::max({1.0, std::fabs(a), std::fabs(b)});
}

// Safeguarded Newton on a bracket [a, b] where p changes sign.
double refine_bracketed(const SturmSequence& s, double a, double b, double fa) {
  double x = 0.5 * (a + b);
  for (int it = 0; it < 100 && b - a > tolerance(a, b); ++it) {
    const double f = s.p()(x);
    if (f == 0) return x;
    if ((f > 0) == (fa > 0)) {
      a = x;
      fa = f;
    } else {
      b = x;
    }
    const double df = s.dp()(x);
    double next = df != 0 ? x - f / df : a - 1;
    if (!(next > a && next < b)) next = 0.5 * (a + b);
    if (std::fabs(next - x) <= tolerance(a, b)) return next;
    x = next;
  }
  return x;
}

// A root of even multiplicity (p touches zero without crossing): bisect on the Sturm count, then let
// Newton on p' (which does cross zero there) finish.
double refine_touching(const SturmSequence& s, double a, double b, int count_b) {
  const double a0 = a, b0 = b;
  for (int it = 0; it < 200 && b - a > 1e3 * tolerance(a, b); ++it) {
    const double m = 0.5 * (a + b);
    if (s.sign_changes(m) > count_b) {
      a = m;
    } else {
      b = m;
    }
  }
  double x = 0.5 * (a + b);
  // Polish only within a few bracket widths: far away p' vanishes at critical points that are no roots.
  const double lo = std::max(a0, a - 4 * (b - a)), hi = std::min(b0, b + 4 * (b - a));
  const Poly ddp = derivative(s.dp());
  for (int it = 0; it < 8; ++it) {
    const double d2 = ddp(x);
    if (d2 == 0) break;
    const double next = x - s.dp()(x) / d2;
    if (!(next > lo && next <= hi)) break;
    if (std::fabs(next - x) <= tolerance(a, b)) {
      x = next;
      break;
    }
    x = next;
  }
  return x;
}

}  // namespace

double evaluate_polynomial(std::span<const double> coeffs, double x) {
  double r = 0;
  for (size_t i = coeffs.size(); i-- > 0;) r = r * x + coeffs[i];
  return r;
}

bool solve_quadratic(double a, double b, double c, double& t0, double& t1) {
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

}  // namespace

int real_roots(std::span<const double> coeffs, double lo, double hi, std::span<double> roots, int max_roots) {
  if (coeffs.size() > static_cast<size_t>(kMaxPolynomialDegree + 1))
    throw std::invalid_argument("real_roots: degree above " + std::to_string(kMaxPolynomialDegree));
  if (!std::isfinite(lo) || !std::isfinite(hi) || !(lo < hi))
    throw std::invalid_argument("real_roots: the interval must be finite and non-empty");
  Poly p;
  p.degree = static_cast<int>(coeffs.size()) - 1;
  for (int i = 0; i <= p.degree; ++i) {
    if (!std::isfinite(coeffs[i])) return 0;
    p.c[i] = coeffs[i];
  }
  p.trim(p.max_abs());
  if (p.degree <= 0) return 0;
  if (roots.size() < static_cast<size_t>(p.degree))
    throw std::invalid_argument("real_roots: output span shorter than the degree");
  // Monic scaling keeps the Sturm remainders' relative-zero test meaningful.
  const double lead = p.c[p.degree];
  for (int i = 0; i <= p.degree; ++i) p.c[i] /= lead;

  if (p.degree == 1) {
    const double r = -p.c[0];
    if (r > lo && r <= hi && max_roots > 0) {
      roots[0] = r;
      return 1;
    }
    return 0;
  }

  if (p.degree == 2) return quadratic_roots(p, lo, hi, roots, max_roots);
  const SturmSequence s(p);
  int n = 0;
  struct Span {
    double a, b;
    int ca, cb;
    int depth;
  };
  std::array<Span, 256> stack;
  int top = 0;
  stack[top++] = {lo, hi, s.sign_changes(lo), s.sign_changes(hi), 0};
  // Spans are walked lowest first, so roots come out in increasing order and the walk can stop early.
  while (top > 0 && n < max_roots) {
    const Span sp = stack[--top];
    const int count = sp.ca - sp.cb;
    if (count <= 0) continue;
    if (count == 1) {
      // At an excluded root a, p just right of a has the sign of p'(a).
      const double fa = p(sp.a) != 0 ? p(sp.a) : s.dp()(sp.a), fb = p(sp.b);
      double r;
      if (fb == 0) {
        r = sp.b;
      } else if (fa != 0 && (fa > 0) != (fb > 0)) {
        r = refine_bracketed(s, sp.a, sp.b, fa);
      } else {
        r = refine_touching(s, sp.a, sp.b, sp.cb);
      }
      if (n < static_cast<int>(roots.size())) roots[n++] = r;
      continue;
    }
    // Several roots closer than we can separate: report the cluster once.
    if (sp.depth > 100 || sp.b - sp.a <= 1e3 * tolerance(sp.a, sp.b) ||
        top + 2 > static_cast<int>(stack.size())) {
      if (n < static_cast<int>(roots.size())) roots[n++] = 0.5 * (sp.a + sp.b);
      continue;
    }
    const double m = 0.5 * (sp.a + sp.b);
    const int cm = s.sign_changes(m);
    // Push the upper half first so the lower half is processed first (roots come out sorted).
    stack[top++] = {m, sp.b, cm, sp.cb, sp.depth + 1};
    stack[top++] = {sp.a, m, sp.ca, cm, sp.depth + 1};
  }
  std::sort(roots.begin(), roots.begin() + n);
  return n;
}

}  // namespace snell::geometry
