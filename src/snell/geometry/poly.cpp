#include "snell/geometry/poly.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "snell/geometry/polynomial.hpp"

namespace snell::geometry {
namespace {

using Coeffs = std::array<double, kMaxPolynomialDegree + 1>;

// (a + b u)^n for n = 0..order, as ascending coefficient arrays.
std::array<Coeffs, kMaxPolynomialDegree + 1> binomial_powers(double a, double b, int order) {
  std::array<Coeffs, kMaxPolynomialDegree + 1> powers{};
  powers[0][0] = 1;
  for (int n = 1; n <= order; ++n) {
    for (int m = 0; m <= n; ++m) {
      powers[n][m] = a * powers[n - 1][m] + (m > 0 ? b * powers[n - 1][m - 1] : 0);
    }
  }
  return powers;
}

double ipow(double x, int n) {
  double r = 1;
  for (int i = 0; i < n; ++i) r *= x;
  return r;
}

}  // namespace

int max_poly_order() {
  return kMaxPolynomialDegree;
}

int poly_coefficient_count(int order) {
  return (order + 1) * (order + 2) * (order + 3) / 6;
}

Poly::Poly(int order, const std::vector<double>& coefficients) : order_(order) {
  if (order < 2 || order > max_poly_order())
    throw std::invalid_argument("poly order must be between 2 and " + std::to_string(max_poly_order()));
  if (static_cast<int>(coefficients.size()) != poly_coefficient_count(order))
    throw std::invalid_argument("poly of order " + std::to_string(order) + " needs " +
                                std::to_string(poly_coefficient_count(order)) + " coefficients, not " +
                                std::to_string(coefficients.size()));
  size_t index = 0;
  for (int i = order; i >= 0; --i) {
    for (int j = order - i; j >= 0; --j) {
      for (int k = order - i - j; k >= 0; --k) {
        const double c = coefficients[index++];
        if (!std::isfinite(c)) throw std::invalid_argument("poly coefficients must be finite");
        if (c != 0) terms_.push_back({i, j, k, c});
      }
    }
  }
  if (terms_.empty()) throw std::invalid_argument("poly has only zero coefficients");
  if (const auto box = poly_negative_region_bounds(terms_)) {
    bounds_ = *box;
    bounded_ = true;
  }
}

double Poly::value(const Vec3& p) const {
  double sum = 0;
  for (const Term& t : terms_) sum += t.c * ipow(p.x, t.i) * ipow(p.y, t.j) * ipow(p.z, t.k);
  return sum;
}

Vec3 Poly::gradient(const Vec3& p) const {
  Vec3 g;
  for (const Term& t : terms_) {
    const double px = ipow(p.x, t.i), py = ipow(p.y, t.j), pz = ipow(p.z, t.k);
    if (t.i > 0) g.x += t.c * t.i * ipow(p.x, t.i - 1) * py * pz;
    if (t.j > 0) g.y += t.c * t.j * px * ipow(p.y, t.j - 1) * pz;
    if (t.k > 0) g.z += t.c * t.k * px * py * ipow(p.z, t.k - 1);
  }
  return g;
}

int Poly::roots_along(const Ray& ray, double t_min, double t_max, double* ts) const {
  // As for the torus: a unit direction and the origin moved to the ray's closest approach to the
  // shape's origin keep the coefficients of the scene's size. A point is o + u dn, u = f + t |d|.
  const double dl = length(ray.direction);
  if (!(dl > 0) || !std::isfinite(dl)) return 0;
  const Vec3 dn = ray.direction / dl;
  const double f = dot(ray.origin, dn);
  const Vec3 o = ray.origin - f * dn;
  const auto px = binomial_powers(o.x, dn.x, order_), py = binomial_powers(o.y, dn.y, order_),
             pz = binomial_powers(o.z, dn.z, order_);
  Coeffs c{};
  for (const Term& t : terms_) {
    // Product of three binomial powers; degrees add up to at most the order.
    Coeffs xy{};
    for (int a = 0; a <= t.i; ++a)
      for (int b = 0; b <= t.j; ++b) xy[static_cast<size_t>(a + b)] += px[t.i][a] * py[t.j][b];
    for (int ab = 0; ab <= t.i + t.j; ++ab)
      for (int e = 0; e <= t.k; ++e) c[static_cast<size_t>(ab + e)] += t.c * xy[ab] * pz[t.k][e];
  }
  // The roots lie within Cauchy's bound 1 + max |c_i / c_n| of the leading surviving coefficient.
  double scale = 0;
  for (const double v : c) scale = std::max(scale, std::fabs(v));
  int degree = order_;
  while (degree > 0 && std::fabs(c[static_cast<size_t>(degree)]) <= 1e-12 * scale) --degree;
  if (degree == 0) return 0;
  double bound = 0;
  for (int i = 0; i < degree; ++i) bound = std::max(bound, std::fabs(c[i] / c[static_cast<size_t>(degree)]));
  bound = std::min(1 + bound, 1e7);
  const double u_lo = std::max(-bound, f + t_min * dl), u_hi = std::min(bound, f + t_max * dl);
  if (!(u_lo < u_hi)) return 0;
  std::array<double, kMaxPolynomialDegree> roots{};
  const int n =
      real_roots(std::span<const double>(c.data(), static_cast<size_t>(degree) + 1), u_lo, u_hi, roots);
  int kept = 0;
  for (int r = 0; r < n; ++r) {
    const double t = (roots[r] - f) / dl;
    if (t > t_min && t < t_max) ts[kept++] = t;
  }
  return kept;
}

bool Poly::intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const {
  double ts[kMaxPolynomialDegree];
  if (roots_along(ray, t_min, t_max, ts) == 0) return false;
  hit = LocalHit{};
  hit.t = ts[0];
  hit.normal = gradient(ray.at(ts[0]));
  if (length_squared(hit.normal) == 0) hit.normal = -ray.direction;  // a singular point
  return true;
}

void Poly::all_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const {
  double ts[kMaxPolynomialDegree];
  const int n = roots_along(ray, t_min, t_max, ts);
  for (int r = 0; r < n; ++r) {
    LocalHit hit;
    hit.t = ts[r];
    hit.normal = gradient(ray.at(ts[r]));
    if (length_squared(hit.normal) == 0) hit.normal = -ray.direction;
    hits.push_back(hit);
  }
}

bool Poly::inside(const Vec3& p) const {
  return value(p) < 0;
}

}  // namespace snell::geometry
