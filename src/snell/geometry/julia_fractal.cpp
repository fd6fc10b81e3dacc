#include "snell/geometry/julia_fractal.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace snell::geometry {

namespace {

/// Marching stops after this many steps (rays that graze the set for long).
constexpr int kMaxSteps = 4000;

double dot4(const Vec4& a, const Vec4& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
}

Vec4 quaternion_product(const Vec4& a, const Vec4& b) {
  return {a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
          a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
          a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
          a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0]};
}

/// Hypercomplex product (commutative; POV-Ray 3.7 reference, "Julia Fractal": ij = ji = k, i^2 = j^2 = -1,
/// k^2 = 1). It factors into two complex products in the components (a - d) and (a + d) of the idempotent
/// basis, which is how it is computed here.
Vec4 hypercomplex_product(const Vec4& a, const Vec4& b) {
  // a = (r, i, j, k): u = (r - k) + (i + j) I, v = (r + k) + (i - j) I.
  const double ur = a[0] - a[3], ui = a[1] + a[2], vr = a[0] + a[3], vi = a[1] - a[2];
  const double br = b[0] - b[3], bi = b[1] + b[2], cr = b[0] + b[3], ci = b[1] - b[2];
  const double pr = ur * br - ui * bi, pi = ur * bi + ui * br;
  const double qr = vr * cr - vi * ci, qi = vr * ci + vi * cr;
  return {0.5 * (pr + qr), 0.5 * (pi + qi), 0.5 * (pi - qi), 0.5 * (qr - pr)};
}

}  // namespace

JuliaFractal::JuliaFractal(const Settings& settings) : s_(settings) {
  if (s_.power != 2 && s_.power != 3)
    throw std::invalid_argument("julia_fractal: only sqr and cube are supported");
  if (s_.max_iteration < 1) throw std::invalid_argument("julia_fractal: max_iteration must be at least 1");
  if (!(s_.precision > 0)) throw std::invalid_argument("julia_fractal: precision must be positive");
  const double n2 = dot4(s_.slice_normal, s_.slice_normal);
  if (!(n2 > 0)) throw std::invalid_argument("julia_fractal: slice normal must not be zero");
  for (double& v : s_.slice_normal) v /= std::sqrt(n2);
  // Gram-Schmidt of the unit axes against the normal; skip the axis closest to it.
  int skip = 0;
  for (int i = 1; i < 4; ++i)
    if (std::fabs(s_.slice_normal[static_cast<std::size_t>(i)]) >
        std::fabs(s_.slice_normal[static_cast<std::size_t>(skip)]))
      skip = i;
  std::vector<Vec4> basis{s_.slice_normal};
  for (int axis = 0, made = 0; axis < 4 && made < 3; ++axis) {
    if (axis == skip) continue;
    Vec4 e{};
    e[static_cast<std::size_t>(axis)] = 1;
    for (const Vec4& b : basis) {
      const double d = dot4(e, b);
      for (int k = 0; k < 4; ++k) e[static_cast<std::size_t>(k)] -= d * b[static_cast<std::size_t>(k)];
    }
    const double len = std::sqrt(dot4(e, e));
    for (double& v : e) v /= len;
    basis.push_back(e);
    e_[made++] = e;
  }
  min_step_ = 0.01 / s_.precision;
}

Vec4 JuliaFractal::step(const Vec4& z) const {
  const auto product = s_.algebra == Algebra::quaternion ? quaternion_product : hypercomplex_product;
  Vec4 next = product(z, z);
  if (s_.power == 3) next = product(next, z);
  for (std::size_t k = 0; k < 4; ++k) next[k] += s_.c[k];
  return next;
}

Vec4 JuliaFractal::lift(const Vec3& p) const {
  Vec4 q;
  for (std::size_t k = 0; k < 4; ++k)
    q[k] = p.x * e_[0][k] + p.y * e_[1][k] + p.z * e_[2][k] + s_.slice_distance * s_.slice_normal[k];
  return q;
}

double JuliaFractal::distance_estimate(const Vec3& p) const {
  Vec4 z = lift(p);
  double dz = 1;  // |z'|, by the chain rule |(z^k)'| = k |z|^(k-1) |z'| (exact for quaternion norms)
  for (int i = 0; i < s_.max_iteration; ++i) {
    const double r = std::sqrt(dot4(z, z));
    if (r > kBailoutRadius) return 0.5 * r * std::log(r) / dz * (2.0 / s_.power);
    // k |z|^(k-1) for k = 2 or 3, without pow (3.4% of benchmark.pov's profile; the same values: pow of
    // an exponent 1 or 2 is exact or one rounding, as the product is).
    dz *= s_.power * (s_.power == 2 ? r : r * r);
    z = step(z);
  }
  return 0;  // did not escape: in the set
}

double JuliaFractal::potential(const Vec3& p) const {
  // Green's function estimate log|z_k| / power^k, iterated past the bailout to a large radius so that it
  // is smooth; its gradient is the surface normal.
  Vec4 z = lift(p);
  double scale = 1;
  for (int i = 0; i < s_.max_iteration; ++i) {
    if (dot4(z, z) > 1e16) break;
    z = step(z);
    scale *= s_.power;
  }
  return 0.5 * std::log(std::max(dot4(z, z), 1e-300)) / scale;
}

bool JuliaFractal::intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const {
  // Clip to the bailout sphere, march by the distance estimate (at least min_step_) until a point stays
  // bounded for max_iteration steps, then bisect back to the boundary of that set, which is the surface
  // POV-Ray draws.
  const double a = dot(ray.direction, ray.direction), b = dot(ray.origin, ray.direction);
  const double disc = b * b - a * (dot(ray.origin, ray.origin) - kBailoutRadius * kBailoutRadius);
  if (disc <= 0) return false;
  const double root = std::sqrt(disc);
  double t = std::max(t_min, (-b - root) / a);
  const double t_end = std::min(t_max, (-b + root) / a);
  const double speed = std::sqrt(a);
  double d = distance_estimate(ray.at(t));
  // Starting on the surface (a shadow or reflected ray): leave the set before looking for a hit.
  for (int i = 0; i < kMaxSteps && d <= 0 && t < t_end; ++i) {
    t += min_step_ / speed;
    d = distance_estimate(ray.at(t));
  }
  double t_out = t;
  for (int i = 0; i < kMaxSteps && t < t_end; ++i) {
    if (d <= 0) {
      double t_in = t;
      for (int k = 0; k < 40 && (t_in - t_out) * speed > 1e-9; ++k) {
        const double mid = 0.5 * (t_out + t_in);
        (distance_estimate(ray.at(mid)) <= 0 ? t_in : t_out) = mid;
      }
      hit = LocalHit{};
      hit.t = t_out;
      const Vec3 p = ray.at(t_out);
      const double h = 1e-5;
      hit.normal = {potential(p + Vec3(h, 0, 0)) - potential(p - Vec3(h, 0, 0)),
                    potential(p + Vec3(0, h, 0)) - potential(p - Vec3(0, h, 0)),
                    potential(p + Vec3(0, 0, h)) - potential(p - Vec3(0, 0, h))};
      if (!(length_squared(hit.normal) > 0) || !is_finite(hit.normal)) hit.normal = -ray.direction;
      return true;
    }
    t_out = t;
    t += std::max(d, min_step_) / speed;
    d = distance_estimate(ray.at(std::min(t, t_end)));
  }
  return false;
}

void JuliaFractal::all_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const {
  LocalHit hit;
  if (intersect(ray, t_min, t_max, hit)) hits.push_back(hit);
}

}  // namespace snell::geometry
