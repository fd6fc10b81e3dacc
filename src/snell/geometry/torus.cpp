#include "snell/geometry/torus.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "snell/geometry/arc_of_revolution.hpp"
#include "snell/geometry/polynomial.hpp"
#include "snell/geometry/surface_uv.hpp"

namespace snell::geometry {

Torus::Torus(double major_radius, double minor_radius) : major_(major_radius), minor_(minor_radius) {
  if (!std::isfinite(major_radius) || !std::isfinite(minor_radius))
    throw std::invalid_argument("torus: radii must be finite");
  if (major_radius < 0) throw std::invalid_argument("torus: major radius must not be negative");
  if (minor_radius <= 0) throw std::invalid_argument("torus: minor radius must be positive");
}

Bounds3 Torus::bounds() const {
  const double r = major_ + minor_;
  return {Vec3(-r, -minor_, -r), Vec3(r, minor_, r)};
}

LocalHit Torus::make_hit(const Vec3& p, double t) const {
  LocalHit h;
  h.t = t;
  const double rho = std::sqrt(p.x * p.x + p.z * p.z);
  // Gradient direction: from the nearest point of the core circle to p.
  Vec3 n = rho > 0 ? p - Vec3(major_ * p.x / rho, 0, major_ * p.z / rho) : Vec3(0, p.y, 0);
  if (length_squared(n) == 0) n = Vec3(0, 1, 0);
  h.normal = normalize(n);
  if (surface_uv_requested())  // two atan2, only for a reader of uv (surface_uv.hpp)
    h.uv = {0.5 + std::atan2(p.z, p.x) * 0.5 * math::kInvPi,
            0.5 + std::atan2(p.y, rho - major_) * 0.5 * math::kInvPi};
  return h;
}

bool Torus::quartic_along(const Ray& ray, double t_min, double t_max, Quartic& q) const {
  // Work with a unit direction and an origin moved to the ray's closest approach to the centre: the
  // quartic's coefficients then stay of the torus' size however far away the ray starts. A point of the
  // ray is o + u dn with u = f + t |d|.
  const double dl = length(ray.direction);
  if (!(dl > 0) || !std::isfinite(dl)) return false;
  const Vec3 dn = ray.direction / dl;
  const double f = dot(ray.origin, dn);
  const Vec3 o = ray.origin - f * dn;
  const double rb = major_ + minor_;
  const double c2 = rb * rb - length_squared(o);
  if (c2 < 0) return false;
  const double half = std::sqrt(c2);
  double u_lo = std::max(-half * 1.000001, f + t_min * dl);
  double u_hi = std::min(half * 1.000001, f + t_max * dl);
  if (!(u_lo < u_hi)) return false;
  // The torus lies within the slab |y| <= minor and the cylinder x^2 + z^2 <= (major + minor)^2 (POV-Ray
  // also tests a bounding cylinder first): the part of the window inside both is all the quartic needs,
  // and a smaller window is more often settled by real_roots' sign test alone. Widened by 1e-6 relative
  // so that clipping never drops a root on the boundary.
  const double slab = minor_ * 1.000001;
  if (dn.y != 0) {
    const double a = (-slab - o.y) / dn.y, b = (slab - o.y) / dn.y;
    u_lo = std::max(u_lo, std::min(a, b));
    u_hi = std::min(u_hi, std::max(a, b));
  } else if (std::fabs(o.y) > slab) {
    return false;
  }
  const double radial = dn.x * dn.x + dn.z * dn.z;
  if (radial > 1e-12) {
    // x^2 + z^2 along the ray: radial u^2 + 2 b u + c, with o perpendicular to dn.
    const double b = o.x * dn.x + o.z * dn.z, c = o.x * o.x + o.z * o.z - rb * rb * 1.000002;
    const double disc = b * b - radial * c;
    if (disc < 0) return false;
    const double root = std::sqrt(disc);
    u_lo = std::max(u_lo, (-b - root) / radial);
    u_hi = std::min(u_hi, (-b + root) / radial);
  }
  if (!(u_lo < u_hi)) return false;
  q = {o, dn, f, dl, u_lo, u_hi, torus_quartic(o, dn, major_, minor_)};
  return true;
}

bool Torus::gather(const Ray& ray, HitBuffer<4>& hits, int max_roots) const {
  Quartic q;
  if (!quartic_along(ray, hits.t_min(), hits.t_max(), q)) return false;
  std::array<double, 4> roots{};
  const int n = real_roots(q.coeffs, q.u_lo, q.u_hi, roots, max_roots);
  bool refused = false;
  for (int i = 0; i < n; ++i) {
    const double t = (roots[i] - q.f) / q.dl;
    if (hits.accepts(t)) {
      hits.add(make_hit(q.o + roots[i] * q.dn, t));
    } else {
      refused = true;
    }
  }
  return refused;
}

bool Torus::crosses(const Ray& ray, double t_min, double t_max) const {
  Quartic q;
  if (!quartic_along(ray, t_min, t_max, q)) return false;
  // A shadow ray asks only whether a root lies in its window, which quartic_along already clipped to
  // (t_min, t_max): has_root settles most blocked rays by the signs at the ends and refines no root (on
  // torus1.pov, 1.9 M of its 2.6 M rays, finding the smallest root was a third of the render).
  return has_root(q.coeffs, q.u_lo, q.u_hi);
}

bool Torus::intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const {
  HitBuffer<4> hits(t_min, t_max);
  // The nearest root is all a nearest hit needs; should rounding push its t out of the window, the
  // next roots may still lie inside: then all of them.
  if (gather(ray, hits, 1)) {
    hits = HitBuffer<4>(t_min, t_max);
    gather(ray, hits);
  }
  return hits.nearest(hit);
}

void Torus::all_hits(const Ray& ray, double t_min, double t_max, HitList& out) const {
  HitBuffer<4> hits(t_min, t_max);
  gather(ray, hits);
  hits.append_sorted(out);
}

bool Torus::inside(const Vec3& p) const {
  const double rho = std::sqrt(p.x * p.x + p.z * p.z) - major_;
  return rho * rho + p.y * p.y < minor_ * minor_;
}

}  // namespace snell::geometry
