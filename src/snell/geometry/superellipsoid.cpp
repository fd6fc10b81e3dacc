#include "snell/geometry/superellipsoid.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "snell/geometry/lipschitz_march.hpp"
#include "snell/math/constants.hpp"

namespace snell::geometry {

namespace {

/// POV-Ray clamps exponents below this to keep powers finite (superellipsoid parsing, MIN_VALUE-like).
constexpr double kMinExponent = 1e-3;
/// Tolerance of roots in the unit box: well below a pixel at any sane scale, far above round-off.
constexpr double kTolerance = 1e-9;
/// Shortest march step in the unit box (grazing rays): features thinner than this are missed.
constexpr double kMinStep = 1e-4;
/// A ray starting this close to the surface (in gauge units, about distance) starts on it.
constexpr double kSurfaceBand = 1e-6;

}  // namespace

Superellipsoid::Superellipsoid(double east_west, double north_south)
    : e_(std::max(east_west, kMinExponent)), n_(std::max(north_south, kMinExponent)) {
  if (!std::isfinite(east_west) || !std::isfinite(north_south))
    throw std::invalid_argument("superellipsoid: exponents must be finite");
  // The gauge of a body symmetric in the axes peaks on the unit sphere at the directions where the body
  // is thinnest; for these shapes those are the axes, face diagonals or the space diagonal.
  const double d2 = 1 / std::sqrt(2.0), d3 = 1 / std::sqrt(3.0);
  lipschitz_ = 1;
  for (const Vec3& u : {Vec3(d2, d2, 0), Vec3(d2, 0, d2), Vec3(d3, d3, d3)})
    lipschitz_ = std::max(lipschitz_, gauge(u));
  lipschitz_ *= 1.05;  // margin for directions between those sampled
}

double Superellipsoid::gauge(const Vec3& p) const {
  const double ax = std::fabs(p.x), ay = std::fabs(p.y), az = std::fabs(p.z);
  // Factor out the largest coordinate so that the powers neither overflow nor underflow for tiny e, n.
  const double m = std::max({ax, ay, az});
  if (m == 0) return 0;
  const double xy = std::pow(ax / m, 2 / e_) + std::pow(ay / m, 2 / e_);
  const double f = std::pow(xy, e_ / n_) + std::pow(az / m, 2 / n_);
  return m * std::pow(f, n_ / 2);
}

Vec3 Superellipsoid::normal(const Vec3& p) const {
  // Gradient of F = A^(e/n) + |z|^(2/n) with A = |x|^(2/e) + |y|^(2/e), without the common factor 2/n.
  const double ax = std::fabs(p.x), ay = std::fabs(p.y), az = std::fabs(p.z);
  const double a = std::pow(ax, 2 / e_) + std::pow(ay, 2 / e_);
  const double outer = a > 0 ? std::pow(a, e_ / n_ - 1) : 0;
  const auto part = [](double v, double exponent) { return v > 0 ? std::pow(v, exponent) : 0.0; };
  Vec3 g{std::copysign(outer * part(ax, 2 / e_ - 1), p.x), std::copysign(outer * part(ay, 2 / e_ - 1), p.y),
         std::copysign(part(az, 2 / n_ - 1), p.z)};
  if (is_finite(g) && length_squared(g) > 0) return g;
  // Central differences of the gauge where the powers blow up (edges of nearly box-like shapes).
  constexpr double h = 1e-6;
  g = {gauge(p + Vec3(h, 0, 0)) - gauge(p - Vec3(h, 0, 0)),
       gauge(p + Vec3(0, h, 0)) - gauge(p - Vec3(0, h, 0)),
       gauge(p + Vec3(0, 0, h)) - gauge(p - Vec3(0, 0, h))};
  return length_squared(g) > 0 ? g : p;
}

template <typename Sink>
void Superellipsoid::trace(const Ray& ray, double t_min, double t_max, Sink&& sink) const {
  // Clip to the bounding box [-1, 1]^3 by slabs.
  double lo = t_min, hi = t_max;
  for (int a = 0; a < 3; ++a) {
    const double d = ray.direction[a], o = ray.origin[a];
    if (d == 0) {
      if (o < -1 || o > 1) return;
      continue;
    }
    double t0 = (-1 - o) / d, t1 = (1 - o) / d;
    if (t0 > t1) std::swap(t0, t1);
    lo = std::max(lo, t0), hi = std::min(hi, t1);
  }
  if (!(lo < hi)) return;
  const double speed = length(ray.direction);
  const auto g = [&](double t) { return gauge(ray.at(t)) - 1; };
  double g_lo = g(lo);
  if (lo == t_min && std::fabs(g_lo) < kSurfaceBand) {
    // The ray leaves the surface (a shadow or reflected ray): step past the root it starts on.
    lo = std::min(hi, lo + 2 * kSurfaceBand / speed);
    g_lo = g(lo);
  }
  const MarchSettings march{lipschitz_ * speed, kMinStep / speed, kTolerance / speed};
  march_roots(
      g, lo, g_lo, hi, march,
      [&](double t) {
        LocalHit hit;
        hit.t = t;
        hit.normal = normal(ray.at(t));
        return sink(hit);
      },
      [](double) {});
}

bool Superellipsoid::intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const {
  bool any = false;
  trace(ray, t_min, t_max, [&](const LocalHit& h) {
    hit = h;
    any = true;
    return false;
  });
  return any;
}

void Superellipsoid::all_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const {
  trace(ray, t_min, t_max, [&](const LocalHit& h) {
    hits.push_back(h);
    return true;
  });
}

}  // namespace snell::geometry
