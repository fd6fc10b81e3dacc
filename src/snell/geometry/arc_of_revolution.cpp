#include "snell/geometry/arc_of_revolution.hpp"

#include <array>
#include <cmath>

#include "snell/geometry/polynomial.hpp"

namespace snell::geometry {

namespace {

double distance_from_axis(const Vec3& p) {
  return std::sqrt(p.x * p.x + p.z * p.z);
}

}  // namespace

std::array<double, 5> torus_quartic(const Vec3& o, const Vec3& dn, double major, double minor) {
  const double r2 = major * major;
  const double g = dot(o, dn);
  const double e = length_squared(o) + r2 - minor * minor;
  return {e * e - 4 * r2 * (o.x * o.x + o.z * o.z), 4 * g * e - 8 * r2 * (o.x * dn.x + o.z * dn.z),
          4 * g * g + 2 * e - 4 * r2 * (dn.x * dn.x + dn.z * dn.z), 4 * g, 1.0};
}

Vec3 ArcOfRevolution::normal_at(const Vec3& p) const {
  // From the nearest point of the circle of centres (radius center_rho, height center_y) towards p.
  const double rho = distance_from_axis(p);
  if (!(rho > 0)) return {0, p.y >= center_y ? 1.0 : -1.0, 0};
  const double k = 1 - center_rho / rho;
  return normalize(Vec3(p.x * k, p.y - center_y, p.z * k));
}

bool ArcOfRevolution::encloses(const Vec3& p) const {
  if (p.y < y_lo || p.y > y_hi) return false;
  const double d = distance_from_axis(p) - center_rho, h = p.y - center_y;
  return d * d + h * h < radius * radius;
}

int ArcOfRevolution::crossings(const Ray& ray, double t_min, double t_max, double* ts, Vec3* normals) const {
  // As Torus::gather: a unit direction and the origin moved to the ray's closest approach to the circle
  // of centres' middle keep the quartic's coefficients of the shape's size; a point is o + u dn with
  // u = f + t |d|.
  const double dl = length(ray.direction);
  if (!(dl > 0) || !std::isfinite(dl)) return 0;
  const Vec3 dn = ray.direction / dl;
  const Vec3 start = ray.origin - Vec3(0, center_y, 0);
  const double f = dot(start, dn);
  const Vec3 o = start - f * dn;
  const double big_r = std::fabs(center_rho), r = radius;
  const double reach = big_r + r;
  const double c2 = reach * reach - length_squared(o);
  if (c2 < 0) return 0;
  const double half = std::sqrt(c2) * 1.000001;
  const double u_lo = std::max(-half, f + t_min * dl), u_hi = std::min(half, f + t_max * dl);
  if (!(u_lo < u_hi)) return 0;

  std::array<double, 4> roots{};
  int n = 0;
  if (big_r < 1e-9 * r) {
    // The centre is on the axis: the arc is a sphere zone (the quartic would have double roots).
    double u0 = 0, u1 = 0;
    if (solve_quadratic(1, 2 * dot(o, dn), length_squared(o) - r * r, u0, u1)) {
      for (const double u : {u0, u1})
        if (u > u_lo && u < u_hi) roots[static_cast<size_t>(n++)] = u;
    }
  } else {
    const std::array<double, 5> coeffs = torus_quartic(o, dn, big_r, r);
    n = real_roots(coeffs, u_lo, u_hi, roots);
  }
  int kept = 0;
  for (int i = 0; i < n; ++i) {
    const Vec3 q = o + roots[static_cast<size_t>(i)] * dn;  // relative to (0, center_y, 0)
    const double y = q.y + center_y;
    if (y < y_lo || y > y_hi) continue;
    // Keep the arc's sheet: the root must be nearer to its circle than to the mirrored one.
    const double rho = distance_from_axis(q);
    const double own = std::fabs((rho - center_rho) * (rho - center_rho) + q.y * q.y - r * r);
    const double mirrored = std::fabs((rho + center_rho) * (rho + center_rho) + q.y * q.y - r * r);
    if (own > mirrored) continue;
    ts[kept] = (roots[static_cast<size_t>(i)] - f) / dl;
    normals[kept] = normal_at(Vec3(q.x, y, q.z));
    ++kept;
  }
  return kept;
}

}  // namespace snell::geometry
