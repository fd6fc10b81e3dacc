#include "snell/function/algebraic_surfaces.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace snell::function::surfaces {

namespace {

/// POV-Ray keeps the field within [-10, 10] so that max_gradient stays finite far from the surface.
double field(double strength, double value) {
  return std::clamp(strength * value, -10.0, 10.0);
}

struct Point {
  double x, y, z, xx, yy, zz;
  explicit Point(const double* a)
      : x(a[0]), y(a[1]), z(a[2]), xx(a[0] * a[0]), yy(a[1] * a[1]), zz(a[2] * a[2]) {}
  double r2() const { return xx + yy + zz; }
};

double cube(double v) {
  return v * v * v;
}

}  // namespace

// Bicorn (a two-horned curve swept round y): y^2 (s^2 - x^2 - z^2) = (x^2 + z^2 + 2 s y - s^2)^2.
double bicorn(const double* a) {
  const Point p(a);
  const double s2 = a[4] * a[4], ring = p.xx + p.zz;
  const double right = ring + 2 * a[4] * p.y - s2;
  return field(a[3], p.yy * (s2 - ring) - right * right);
}

// Bifolia: (x^2 + y^2 + z^2)^2 = s (x^2 + z^2) y.
double bifolia(const double* a) {
  const Point p(a);
  return field(a[3], a[4] * (p.xx + p.zz) * p.y - p.r2() * p.r2());
}

// Crossed trough: x^2 z^2 = y.
double crossed_trough(const double* a) {
  const Point p(a);
  return field(a[3], p.xx * p.zz - p.y);
}

// Cubic saddle: x^3 - y^3 = z.
double cubic_saddle(const double* a) {
  const Point p(a);
  return field(a[3], p.z - cube(p.x) + cube(p.y));
}

// Devil's curve swept in z: x^4 + 2 x^2 z^2 - 0.36 x^2 - y^4 + 0.25 y^2 + z^4 = 0.
double devils_curve(const double* a) {
  const Point p(a);
  return field(a[3],
               -(p.xx * p.xx + 2 * p.xx * p.zz - 0.36 * p.xx - p.yy * p.yy + 0.25 * p.yy + p.zz * p.zz));
}

// Glob: y^2 + z^2 = 0.5 x^5 + 0.5 x^4.
double glob(const double* a) {
  const Point p(a);
  return field(a[3], 0.5 * p.xx * p.xx * (p.x + 1) - (p.yy + p.zz));
}

// Heart: (2 x^2 + y^2 + z^2 - 1)^3 = 0.1 x^2 z^3 + y^2 z^3.
double heart(const double* a) {
  const Point p(a);
  const double z3 = p.zz * p.z;
  return field(a[3], (0.1 * p.xx + p.yy) * z3 - cube(2 * p.xx + p.yy + p.zz - 1));
}

// Hunt's surface: 4 (x^2 + y^2 + z^2 - 13)^3 + 27 (3 x^2 + y^2 - 4 z^2 - 12)^2 = 0.
double hunt_surface(const double* a) {
  const Point p(a);
  const double q = 3 * p.xx + p.yy - 4 * p.zz - 12;
  return field(a[3], -(4 * cube(p.r2() - 13) + 27 * q * q));
}

// Klein bottle (figure eight immersion): with r = x^2 + y^2 + z^2,
// (r + 2y - 1) ((r - 2y - 1)^2 - 8 z^2) + 16 x z (r - 2y - 1) = 0.
double klein_bottle(const double* a) {
  const Point p(a);
  const double lower = p.r2() - 2 * p.y - 1;
  return field(a[3], -((p.r2() + 2 * p.y - 1) * (lower * lower - 8 * p.zz) + 16 * p.x * p.z * lower));
}

// Kummer surface (one of its quartic forms): x^4 + y^4 + z^4 - x^2 - y^2 - z^2 - x^2 y^2 - x^2 z^2 - y^2 z^2
// + 1.
double kummer_surface_v1(const double* a) {
  const Point p(a);
  const double quartic = p.xx * p.xx + p.yy * p.yy + p.zz * p.zz;
  const double mixed = p.xx * p.yy + p.xx * p.zz + p.yy * p.zz;
  return field(a[3], -(quartic - p.r2() - mixed + 1));
}

// Mitre: 4 x^2 (x^2 + y^2 + z^2) = y^2 (1 - y^2 - z^2).
double mitre(const double* a) {
  const Point p(a);
  return field(a[3], p.yy * (1 - p.yy - p.zz) - 4 * p.xx * p.r2());
}

// Nodal cubic (swept along x): y^3 + z^3 = 6 y z.
double nodal_cubic(const double* a) {
  const Point p(a);
  return field(a[3], 6 * p.y * p.z - cube(p.y) - cube(p.z));
}

// Paraboloid: y = x^2 + z^2.
double paraboloid(const double* a) {
  const Point p(a);
  return field(a[3], p.y - p.xx - p.zz);
}

// Pillow: x^4 + y^4 + z^4 = x^2 + y^2 + z^2 (positive outside, as POV-Ray returns it).
double pillow(const double* a) {
  const Point p(a);
  return field(a[3], p.xx * p.xx + p.yy * p.yy + p.zz * p.zz - p.r2());
}

// Piriform (pear) swept round x: x^4 - x^3 + y^2 + z^2 = 0; POV-Ray negates its clamped field.
double piriform(const double* a) {
  const Point p(a);
  return -field(a[3], -(p.xx * p.xx - p.xx * p.x + p.yy + p.zz));
}

// Quartic paraboloid: y = x^4 + z^4.
double quartic_paraboloid(const double* a) {
  const Point p(a);
  return field(a[3], p.y - p.xx * p.xx - p.zz * p.zz);
}

// Quartic saddle: y = x^4 - z^4.
double quartic_saddle(const double* a) {
  const Point p(a);
  return field(a[3], p.y - p.xx * p.xx + p.zz * p.zz);
}

// Steiner's Roman surface: x^2 y^2 + x^2 z^2 + y^2 z^2 + x y z = 0.
double steiners_roman(const double* a) {
  const Point p(a);
  return field(a[3], -(p.xx * p.yy + p.xx * p.zz + p.yy * p.zz + p.x * p.y * p.z));
}

// Torus with its axis along y in quartic form, major radius R, minor radius r:
// (x^2 + y^2 + z^2)^2 - 2 (R^2 + r^2)(x^2 + z^2) + 2 (R^2 - r^2) y^2 + (R^2 - r^2)^2 = 0.
double torus2(const double* a) {
  const Point p(a);
  const double big = a[4] * a[4], small = a[5] * a[5];
  const double quartic = p.r2() * p.r2() - 2 * (big + small) * (p.xx + p.zz) + 2 * (big - small) * p.yy +
                         (big - small) * (big - small);
  return field(a[3], -quartic);
}

// Torus gumdrop: 4 (x^4 + (y^2 + z^2)^2) + 17 x^2 (y^2 + z^2) - 20 (x^2 + y^2 + z^2) + 17 = 0.
double torus_gumdrop(const double* a) {
  const Point p(a);
  const double round = p.yy + p.zz;
  return field(a[3], -(4 * (p.xx * p.xx + round * round) + 17 * p.xx * round - 20 * p.r2() + 17));
}

// Umbrella (Whitney): x^2 = y z^2.
double umbrella(const double* a) {
  const Point p(a);
  return field(a[3], p.y * p.zz - p.xx);
}

// Witch of Agnesi swept round y: y (x^2 + z^2 + a) = a.
double witch_of_agnesi(const double* a) {
  const Point p(a);
  return field(a[3], -(a[4] * (p.y - 1) + (p.xx + p.zz) * p.y));
}

// Cushion: z^2 x^2 - z^4 - 2 z x^2 + 2 z^3 + x^2 - z^2 - (x^2 - z)^2 - y^4 - 2 x^2 y^2 - y^2 z^2 + 2 y^2 z +
// y^2 = 0 (positive inside as written; functions.inc's f_odd is the same quartic).
double cushion(const double* a) {
  const Point p(a);
  const double lift = p.xx - p.z;
  const double value = p.zz * p.xx - p.zz * p.zz - 2 * p.z * p.xx + 2 * p.zz * p.z + p.xx - p.zz -
                       lift * lift - p.yy * p.yy - 2 * p.xx * p.yy - p.yy * p.zz + 2 * p.yy * p.z + p.yy;
  return field(a[3], value);
}

// Folium surface swept round x: (y^2 + z^2)(1 + (c - 4 a) x) + x^2 (1 + c) = 0, a the neck width, c the
// divergence.
double folium_surface(const double* a) {
  const Point p(a);
  return field(a[3], (p.yy + p.zz) * (1 + (a[5] - 4 * a[4]) * p.x) + p.xx * (1 + a[5]));
}

// Hyperbolic torus: the torus quartic with z^2 counted negative, R major and r minor radius.
double hyperbolic_torus(const double* a) {
  const Point p(a);
  const double big = a[4] * a[4], small = a[5] * a[5];
  const double quartic = p.xx * p.xx + 2 * p.xx * p.yy - 2 * p.xx * p.zz - 2 * (big + small) * p.xx +
                         p.yy * p.yy - 2 * p.yy * p.zz + 2 * (big - small) * p.yy + p.zz * p.zz +
                         2 * (big + small) * p.zz + (big - small) * (big - small);
  return field(a[3], -quartic);
}

// Kampyle of Eudoxus swept round x: y^2 + z^2 = c^2 x^4 - c^2 d^2 x^2, d the dimple, c the closeness.
double kampyle_of_eudoxus(const double* a) {
  const Point p(a);
  const double c2 = a[5] * a[5];
  return field(a[3], c2 * p.xx * p.xx - c2 * a[4] * a[4] * p.xx - (p.yy + p.zz));
}

// Kummer surface with parameters: x^4 + y^4 + z^4 + a (x^2 + y^2 + z^2) + b (x^2 y^2 + x^2 z^2 + y^2 z^2)
// + c x y z = 1.
double kummer_surface_v2(const double* a) {
  const Point p(a);
  const double value = p.xx * p.xx + p.yy * p.yy + p.zz * p.zz + a[4] * p.r2() +
                       a[5] * (p.xx * p.yy + p.xx * p.zz + p.yy * p.zz) + a[6] * p.x * p.y * p.z - 1;
  return field(a[3], -value);
}

// Lemniscate of Gerono swept round x: x^4 - x^2 + y^2 + z^2 = 0.
double lemniscate_of_gerono(const double* a) {
  const Point p(a);
  return field(a[3], p.xx - p.xx * p.xx - p.yy - p.zz);
}

// Ovals of Cassini swept round y: (x^2 + y^2 + z^2 + R^2)^2 = t R^2 (x^2 + z^2) + f^2, R the radius,
// f the filling, t the thickness.
double ovals_of_cassini(const double* a) {
  const Point p(a);
  const double r2 = a[4] * a[4], sum = p.r2() + r2;
  return field(a[3], a[6] * r2 * (p.xx + p.zz) + a[5] * a[5] - sum * sum);
}

// Parabolic torus: x^4 + 2 x^2 y^2 - 2 x^2 z - (R^2 + r^2) x^2 + y^4 - 2 y^2 z + (R^2 - r^2) y^2 + z^2
// + (R^2 + r^2) z + (R^2 - r^2)^2 = 0.
double parabolic_torus(const double* a) {
  const Point p(a);
  const double big = a[4] * a[4], small = a[5] * a[5];
  const double quartic = p.xx * p.xx + 2 * p.xx * p.yy - 2 * p.xx * p.z - (big + small) * p.xx + p.yy * p.yy -
                         2 * p.yy * p.z + (big - small) * p.yy + p.zz + (big + small) * p.z +
                         (big - small) * (big - small);
  return field(a[3], -quartic);
}

// Quartic cylinder round y: (x^2 + z^2) y^2 + b^2 (x^2 + z^2) = b^2 d^2, d the diameter, b the bulge.
double quartic_cylinder(const double* a) {
  const Point p(a);
  const double ring = p.xx + p.zz, b2 = a[5] * a[5];
  return field(a[3], b2 * a[4] * a[4] - ring * p.yy - b2 * ring);
}

// Strophoid swept round x: (c - x)(y^2 + z^2) = f^2 b x^2 + f^2 x^3, b the size of the bulb, c the
// sharpness, f the flatness.
double strophoid(const double* a) {
  const Point p(a);
  const double f2 = a[6] * a[6];
  return field(a[3], f2 * a[4] * p.xx + f2 * p.xx * p.x - (a[5] - p.x) * (p.yy + p.zz));
}

namespace {
/// The three Gaussians, each stretched by the eccentricity e along two axes: exp(-s (e x^2 + e y^2 + z^2))...
std::array<double, 3> stretched_gaussians(const double* a) {
  const Point p(a);
  const double e = a[3], s = a[4];
  return {std::exp(-(p.xx * e + p.yy * e + p.zz) * s), std::exp(-(p.xx * e + p.yy + p.zz * e) * s),
          std::exp(-(p.xx + p.yy * e + p.zz * e) * s)};
}
}  // namespace

double cross_ellipsoids(const double* a) {
  const auto g = stretched_gaussians(a);
  return a[6] - std::max({g[0], g[1], g[2]}) * a[5];
}

double isect_ellipsoids(const double* a) {
  const auto g = stretched_gaussians(a);
  return a[6] - std::min({g[0], g[1], g[2]}) * a[5];
}

}  // namespace snell::function::surfaces
