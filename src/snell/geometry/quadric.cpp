#include "snell/geometry/quadric.hpp"

#include <cmath>
#include <stdexcept>

#include "snell/geometry/polynomial.hpp"

namespace snell::geometry {

Quadric::Quadric(const Vec3& squares, const Vec3& mixed, const Vec3& linear, double constant)
    : sq_(squares), mix_(mixed), lin_(linear), j_(constant) {
  if (!is_finite(sq_) || !is_finite(mix_) || !is_finite(lin_) || !std::isfinite(j_))
    throw std::invalid_argument("quadric coefficients must be finite");
  if (sq_ == Vec3(0) && mix_ == Vec3(0) && lin_ == Vec3(0))
    throw std::invalid_argument("quadric has no x, y or z term: it is not a surface");
  bounds_ = compute_bounds();
}

double Quadric::value(const Vec3& p) const {
  return p.x * (sq_.x * p.x + mix_.x * p.y + mix_.y * p.z + lin_.x) +
         p.y * (sq_.y * p.y + mix_.z * p.z + lin_.y) + p.z * (sq_.z * p.z + lin_.z) + j_;
}

Vec3 Quadric::gradient(const Vec3& p) const {
  return {2 * sq_.x * p.x + mix_.x * p.y + mix_.y * p.z + lin_.x,
          2 * sq_.y * p.y + mix_.x * p.x + mix_.z * p.z + lin_.y,
          2 * sq_.z * p.z + mix_.y * p.x + mix_.z * p.y + lin_.z};
}

Bounds3 Quadric::compute_bounds() const {
  // Write the value as (p - c)^T M (p - c) + k with M symmetric. When M is positive definite the inside
  // {value < 0} is an ellipsoid whose half-extent along axis i is sqrt(-k (M^-1)_ii); otherwise (or with
  // k >= 0, an empty inside) the surface is left unbounded like POV-Ray's general quadric.
  const double m[3][3] = {
      {sq_.x, mix_.x / 2, mix_.y / 2}, {mix_.x / 2, sq_.y, mix_.z / 2}, {mix_.y / 2, mix_.z / 2, sq_.z}};
  const double minor1 = m[0][0];
  const double minor2 = m[0][0] * m[1][1] - m[0][1] * m[1][0];
  const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                     m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                     m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  if (!(minor1 > 0 && minor2 > 0 && det > 0)) return Bounds3::infinite();  // Sylvester's criterion
  double inv[3][3];
  inv[0][0] = (m[1][1] * m[2][2] - m[1][2] * m[2][1]) / det;
  inv[0][1] = (m[0][2] * m[2][1] - m[0][1] * m[2][2]) / det;
  inv[0][2] = (m[0][1] * m[1][2] - m[0][2] * m[1][1]) / det;
  inv[1][1] = (m[0][0] * m[2][2] - m[0][2] * m[2][0]) / det;
  inv[1][2] = (m[0][2] * m[1][0] - m[0][0] * m[1][2]) / det;
  inv[2][2] = (m[0][0] * m[1][1] - m[0][1] * m[1][0]) / det;
  inv[1][0] = inv[0][1];
  inv[2][0] = inv[0][2];
  inv[2][1] = inv[1][2];
  // The centre solves grad = 0: 2 M c + (G, H, I) = 0.
  const double g[3] = {lin_.x, lin_.y, lin_.z};
  double c[3];
  for (int i = 0; i < 3; ++i) c[i] = -0.5 * (inv[i][0] * g[0] + inv[i][1] * g[1] + inv[i][2] * g[2]);
  const Vec3 center(c[0], c[1], c[2]);
  const double k = value(center);
  if (!(k < 0)) return {};  // empty inside: nothing to hit
  const Vec3 half(std::sqrt(-k * inv[0][0]), std::sqrt(-k * inv[1][1]), std::sqrt(-k * inv[2][2]));
  // A relative margin keeps rounding of the hit points inside the box.
  const Vec3 pad = half * 1e-9 + Vec3(1e-12);
  return {center - half - pad, center + half + pad};
}

namespace {

/// The gradient vanishes only at singular points (a cone's apex); face the ray there.
Vec3 usable_normal(const Vec3& gradient, const Ray& ray) {
  return length_squared(gradient) > 0 ? gradient : -ray.direction;
}

}  // namespace

int Quadric::roots(const Ray& ray, double t[2]) const {
  const Vec3& o = ray.origin;
  const Vec3& d = ray.direction;
  // value(o + t d) = a t^2 + b t + c.
  const double a = sq_.x * d.x * d.x + sq_.y * d.y * d.y + sq_.z * d.z * d.z + mix_.x * d.x * d.y +
                   mix_.y * d.x * d.z + mix_.z * d.y * d.z;
  const double b = dot(gradient(o), d);
  const double c = value(o);
  // A direction along which the quadratic part vanishes (relative to its scale) leaves a line.
  const double scale = (std::fabs(sq_.x) + std::fabs(sq_.y) + std::fabs(sq_.z) + std::fabs(mix_.x) +
                        std::fabs(mix_.y) + std::fabs(mix_.z)) *
                       dot(d, d);
  if (std::fabs(a) <= 1e-12 * scale) {
    if (b == 0) return 0;
    t[0] = -c / b;
    return std::isfinite(t[0]) ? 1 : 0;
  }
  double t0, t1;
  if (!solve_quadratic(a, b, c, t0, t1)) return 0;
  t[0] = t0;
  t[1] = t1;
  return t0 == t1 ? 1 : 2;
}

bool Quadric::intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const {
  double t[2];
  const int n = roots(ray, t);
  for (int i = 0; i < n; ++i) {
    if (t[i] > t_min && t[i] < t_max) {
      hit = LocalHit{};
      hit.t = t[i];
      hit.normal = usable_normal(gradient(ray.at(t[i])), ray);
      return true;
    }
  }
  return false;
}

void Quadric::all_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const {
  double t[2];
  const int n = roots(ray, t);
  for (int i = 0; i < n; ++i) {
    if (!(t[i] > t_min && t[i] < t_max)) continue;
    LocalHit hit;
    hit.t = t[i];
    hit.normal = usable_normal(gradient(ray.at(t[i])), ray);
    hits.push_back(hit);
  }
}

}  // namespace snell::geometry
