// Spline evaluation. Segment choice and end behaviour follow POV-Ray's documented semantics (reference,
// "Splines"): linear joins neighbours; quadratic fits a parabola through three neighbours; cubic is a
// Catmull-Rom spline whose first and last points only steer the tangents; natural is the C2 cubic with
// zero curvature at both ends (Burden & Faires, "Numerical Analysis", natural cubic spline algorithm).
#include "snell/sdl/spline.hpp"

#include <algorithm>

namespace snell::sdl {

namespace {

using Points = std::vector<Spline::Point>;

/// Index of the first point whose t is greater than `t` (0: before the spline, size: after it).
size_t segment_end(const Points& p, double t) {
  return static_cast<size_t>(
      std::upper_bound(p.begin(), p.end(), t, [](double x, const Spline::Point& q) { return x < q.t; }) -
      p.begin());
}

double linear(const Points& p, size_t i, int k, double t) {
  const double a = p[i].t, b = p[i + 1].t;
  const double s = (t - a) / (b - a);
  return p[i].value[size_t(k)] + s * (p[i + 1].value[size_t(k)] - p[i].value[size_t(k)]);
}

/// The parabola through points i-1, i, i+1 (Lagrange form).
double quadratic(const Points& p, size_t i, int k, double t) {
  const double t0 = p[i - 1].t, t1 = p[i].t, t2 = p[i + 1].t;
  const size_t c = size_t(k);
  return p[i - 1].value[c] * (t - t1) * (t - t2) / ((t0 - t1) * (t0 - t2)) +
         p[i].value[c] * (t - t0) * (t - t2) / ((t1 - t0) * (t1 - t2)) +
         p[i + 1].value[c] * (t - t0) * (t - t1) / ((t2 - t0) * (t2 - t1));
}

/// Catmull-Rom on segment i..i+1 with tangents from the mean of the neighbouring slopes (a cubic
/// Hermite curve).
double catmull_rom(const Points& p, size_t i, int k, double t) {
  const size_t c = size_t(k);
  const double dt = p[i + 1].t - p[i].t;
  const double u = (t - p[i].t) / dt;
  const auto slope = [&](size_t a) { return (p[a + 1].value[c] - p[a].value[c]) / (p[a + 1].t - p[a].t); };
  const double m0 = (slope(i - 1) + slope(i)) / 2 * dt;
  const double m1 = (slope(i) + slope(i + 1)) / 2 * dt;
  const double u2 = u * u, u3 = u2 * u;
  return p[i].value[c] * (2 * u3 - 3 * u2 + 1) + p[i + 1].value[c] * (3 * u2 - 2 * u3) +
         m0 * (u3 - 2 * u2 + u) + m1 * (u3 - u2);
}

/// Second derivatives of the natural cubic spline through the points' component k (tridiagonal solve).
std::vector<double> natural_curvatures(const Points& p, int k) {
  const size_t n = p.size();
  const size_t c = size_t(k);
  std::vector<double> m(n, 0.0);
  if (n < 3) return m;
  std::vector<double> diag(n, 0.0), rhs(n, 0.0);
  const auto h = [&](size_t i) { return p[i + 1].t - p[i].t; };
  for (size_t i = 1; i + 1 < n; ++i) {
    diag[i] = 2 * (h(i - 1) + h(i));
    rhs[i] =
        6 * ((p[i + 1].value[c] - p[i].value[c]) / h(i) - (p[i].value[c] - p[i - 1].value[c]) / h(i - 1));
  }
  for (size_t i = 2; i + 1 < n; ++i) {  // forward elimination
    const double f = h(i - 1) / diag[i - 1];
    diag[i] -= f * h(i - 1);
    rhs[i] -= f * rhs[i - 1];
  }
  for (size_t i = n - 2; i >= 1; --i) m[i] = (rhs[i] - h(i) * m[i + 1]) / diag[i];
  return m;
}

double natural(const Points& p, const std::vector<double>& m, size_t i, int k, double t) {
  const size_t c = size_t(k);
  const double h = p[i + 1].t - p[i].t;
  const double a = p[i + 1].t - t, b = t - p[i].t;
  return m[i] * a * a * a / (6 * h) + m[i + 1] * b * b * b / (6 * h) +
         (p[i].value[c] / h - m[i] * h / 6) * a + (p[i + 1].value[c] / h - m[i + 1] * h / 6) * b;
}

}  // namespace

void Spline::add(double t, const std::array<double, 5>& value) {
  const size_t at = segment_end(points, t);
  points.insert(points.begin() + static_cast<std::ptrdiff_t>(at), Point{t, value});
}

std::array<double, 5> Spline::evaluate(double t, Kind how) const {
  std::array<double, 5> r{};
  if (points.empty()) return r;
  if (points.size() == 1) return points.front().value;
  const size_t n = points.size();
  const size_t i = segment_end(points, t);
  if (how == Kind::cubic) {
    // The curve runs from the second point to the next-to-last; two points give their mean.
    for (int k = 0; k < 5; ++k) {
      const size_t c = size_t(k);
      if (n == 2)
        r[c] = (points[0].value[c] + points[1].value[c]) / 2;
      else if (i < 2)
        r[c] = points[1].value[c];
      else if (i >= n - 1)
        r[c] = points[n - 2].value[c];
      else
        r[c] = catmull_rom(points, i - 1, k, t);
    }
    return r;
  }
  if (i == 0) return points.front().value;
  if (i >= n) return points.back().value;
  for (int k = 0; k < 5; ++k) {
    const size_t c = size_t(k);
    if (how == Kind::linear || n == 2)
      r[c] = linear(points, i - 1, k, t);
    else if (how == Kind::quadratic)
      r[c] = quadratic(points, i > 1 ? i - 1 : i, k, t);
    else
      r[c] = natural(points, natural_curvatures(points, k), i - 1, k, t);
  }
  return r;
}

}  // namespace snell::sdl
