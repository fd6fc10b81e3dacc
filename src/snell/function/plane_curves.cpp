#include "snell/function/plane_curves.hpp"

#include <algorithm>
#include <cmath>

namespace snell::function::curves {

namespace {

constexpr double kDegrees = 3.14159265358979323846 / 180;

double field(double strength, double value) {
  return std::clamp(strength * value, -10.0, 10.0);
}

/// The curve's plane coordinates for a point: (x, y) as they are (extruded along z), or, with a positive
/// sweep flag, (distance from the y axis minus `distance`, y) turned by `angle` degrees in that plane.
struct PlanePoint {
  double x, y, xx, yy;
  PlanePoint(const double* a, double sweep, double distance, double angle) : x(a[0]), y(a[1]) {
    if (sweep > 0) {
      const double radial = std::sqrt(a[0] * a[0] + a[2] * a[2]) - distance;
      const double t = angle * kDegrees;
      if (t != 0) {
        x = radial * std::cos(t) - a[1] * std::sin(t);
        y = radial * std::sin(t) + a[1] * std::cos(t);
      } else {
        x = radial;
      }
    }
    xx = x * x;
    yy = y * y;
  }
};

}  // namespace

// Devil's curve: x^2 (x^2 - a^2) = y^2 (y^2 - b^2).
double devils_curve_2d(const double* a) {
  const PlanePoint p(a, a[6], a[7], a[8]);
  return field(a[3], p.yy * (p.yy - a[5] * a[5]) - p.xx * (p.xx - a[4] * a[4]));
}

// Folium: y^2 (1 + (c - 4 n) x) + x^2 (1 + c) = 0.
double folium_surface_2d(const double* a) {
  const PlanePoint p(a, a[6], a[7], a[8]);
  return field(a[3], -(p.yy * (1 + (a[5] - 4 * a[4]) * p.x) + p.xx * (1 + a[5])));
}

// Kampyle of Eudoxus: y^2 = c^2 x^4 - c^2 d c x^2 (POV-Ray multiplies by the dimple once and the
// closeness three times here, unlike the swept f_kampyle_of_eudoxus; kept as it draws).
double kampyle_of_eudoxus_2d(const double* a) {
  const PlanePoint p(a, a[6], a[7], a[8]);
  const double c2 = a[5] * a[5];
  return field(a[3], c2 * p.xx * p.xx - c2 * a[4] * a[5] * p.xx - p.yy);
}

// Lemniscate of Gerono: y^2 = w^2 s^2 x^2 - w^2 x^4.
double lemniscate_of_gerono_2d(const double* a) {
  const PlanePoint p(a, a[6], a[7], a[8]);
  const double w2 = a[5] * a[5];
  return field(a[3], w2 * a[4] * a[4] * p.xx - w2 * p.xx * p.xx - p.yy);
}

// Piriform: y^2 = f3 k^2 x^3 + f4 k^2 x^4.
double piriform_2d(const double* a) {
  const PlanePoint p(a, a[7], a[8], a[9]);
  const double k2 = a[6] * a[6];
  return field(a[3], a[4] * k2 * p.xx * p.x + a[5] * k2 * p.xx * p.xx - p.yy);
}

// Strophoid: (c - x) y^2 = f^2 b x^2 + f^2 x^3.
double strophoid_2d(const double* a) {
  const PlanePoint p(a, a[7], a[8], a[9]);
  const double f2 = a[6] * a[6];
  return field(a[3], f2 * a[4] * p.xx + f2 * p.xx * p.x - (a[5] - p.x) * p.yy);
}

// Witch of Agnesi: y (x^2 + a^2) = b.
double witch_of_agnesi_2d(const double* a) {
  const PlanePoint p(a, a[6], a[7], a[8]);
  return field(a[3], a[5] - (a[4] * a[4] + p.xx) * p.y);
}

// Spikes: a round Gaussian of the given roundness and fatness minus three Gaussians stretched along the
// axes by the spikiness and sharpened by the hollowness, scaled by -size.
double spikes(const double* a) {
  const double xx = a[0] * a[0], yy = a[1] * a[1], zz = a[2] * a[2];
  const double e = a[3], s = a[4];
  const double value = std::exp(-(xx + yy + zz) * a[6]) * a[7] - std::exp(-(xx * e + yy * e + zz) * s) -
                       std::exp(-(xx * e + yy + zz * e) * s) - std::exp(-(xx + yy * e + zz * e) * s);
  return -value * a[5];
}

// Spikes on a plane: y = h cos(fx x) cos(fz z) exp(-r (x^2 + z^2)).
double spikes_2d(const double* a) {
  const double decay = std::exp(-a[6] * (a[0] * a[0] + a[2] * a[2]));
  return a[1] - a[3] * std::cos(a[4] * a[0]) * std::cos(a[5] * a[2]) * decay;
}

// Two Gaussian-like blobs at x = -s/2 and x = s/2: each (1 - min(1, d^2 k^2))^2 times its strength.
double blob(const double* a) {
  const double rest = a[1] * a[1] + a[2] * a[2], half = a[3] * 0.5;
  const double near = std::min(1.0, ((a[0] + half) * (a[0] + half) + rest) * a[5] * a[5]);
  const double far = std::min(1.0, ((a[0] - half) * (a[0] - half) + rest) * a[7] * a[7]);
  return -(a[4] * (1 - near) * (1 - near) + a[6] * (1 - far) * (1 - far));
}

// Two Gaussians at the origin and at x = s: threshold - strength (g1 + g2).
double blob2(const double* a) {
  const double rest = a[1] * a[1] + a[2] * a[2], dx = a[0] - a[3];
  const double sum = std::exp(-(a[0] * a[0] + rest) * a[4]) + std::exp(-(dx * dx + rest) * a[4]);
  return a[6] - sum * a[5];
}

// A solid of revolution round y whose radius is c0 + c1 y + c2 y^2 + c3 y^3 + c4 y^4 (not below -5).
double poly4(const double* a) {
  const double y = a[1];
  const double radius = std::max(-5.0, a[3] + y * (a[4] + y * (a[5] + y * (a[6] + y * a[7]))));
  return std::sqrt(a[0] * a[0] + a[2] * a[2]) - radius;
}

namespace {
/// The algebraic cylinders clamp to +-limit instead of +-10.
double limited(double strength, double limit, double value) {
  return std::clamp(strength * value, -limit, limit);
}
constexpr double kPi = 3.14159265358979323846;
}  // namespace

// Algebraic cylinder 1: |x|^3 - x^2 + y^2 = 0 in the curve's plane; POV-Ray negates this one's field.
// Without a sweep the squares are the point's own, with one those of the swept plane point.
double algbr_cyl1(const double* a) {
  const PlanePoint p(a, a[5], a[6], a[7]);
  return -limited(a[3], a[4], -(p.xx * std::fabs(p.x) - p.xx + p.yy));
}

// Algebraic cylinder 2: 2 x^4 - 3 x^2 y + y^2 - 2 y^3 + y^4 = 0.
double algbr_cyl2(const double* a) {
  const PlanePoint p(a, a[5], a[6], a[7]);
  return limited(a[3], a[4], -(2 * p.xx * p.xx - 3 * p.xx * p.y + p.yy - 2 * p.yy * p.y + p.yy * p.yy));
}

// Algebraic cylinder 3: x^4 + x^2 y^2 - 2 x^2 y - x y^2 + y^2 = 0.
double algbr_cyl3(const double* a) {
  const PlanePoint p(a, a[5], a[6], a[7]);
  return limited(a[3], a[4], -(p.xx * p.xx + p.xx * p.yy - 2 * p.xx * p.y - p.x * p.yy + p.yy));
}

// Algebraic cylinder 4: x^4 + y^4 + 2 x^2 y^2 + 3 x^2 y - y^3 = 0.
double algbr_cyl4(const double* a) {
  const PlanePoint p(a, a[5], a[6], a[7]);
  return limited(a[3], a[4], -(p.xx * p.xx + p.yy * p.yy + 2 * p.xx * p.yy + 3 * p.xx * p.y - p.yy * p.y));
}

// Flange cover: threshold - size (sum of three Gaussians stretched along the axes by the spikiness).
double flange_cover(const double* a) {
  const double xx = a[0] * a[0], yy = a[1] * a[1], zz = a[2] * a[2], e = a[3], s = a[4];
  const double sum = std::exp(-(xx * e + yy * e + zz) * s) + std::exp(-(xx * e + yy + zz * e) * s) +
                     std::exp(-(xx + yy * e + zz * e) * s);
  return a[6] - sum * a[5];
}

// Poly tubes: n tubes parallel to y on a circle whose radius is a quartic in y; distance to the nearest.
double polytubes(const double* a) {
  const double y = a[1];
  const double radius = a[4] + y * (a[5] + y * (a[6] + y * (a[7] + y * a[8])));
  const int tubes = static_cast<int>(std::clamp(a[3], -1.0, 4096.0));
  double nearest = 10000;
  for (int i = 0; i < tubes; ++i) {
    const double angle = 2 * kPi / a[3] * i;
    const double dx = a[0] - radius * std::sin(angle), dz = a[2] - radius * std::cos(angle);
    nearest = std::min(nearest, std::sqrt(dx * dx + dz * dz));
  }
  return nearest;
}

// Spiral: a band wound round y with the given step, its cross-section a superellipse of exponent
// `shape` (1 round, 0 square), thickness and outer radius.
double spiral(const double* a) {
  double x = a[0];
  const double y = a[1], z = a[2], step = a[3];
  const double around = std::sqrt(x * x + z * z);
  if (x == 0 && z == 0) x = 0.000001;
  const double unwound = around + step * std::atan2(z, x) / (2 * kPi);
  double across = std::fmod(unwound, step) - step * 0.5;
  const double shape = a[8];
  if (shape == 1) {
    across = std::sqrt(across * across + y * y);
  } else if (shape != 0) {
    const double e = 2 / shape;
    across = std::pow(std::pow(std::fabs(across), e) + std::pow(std::fabs(y), e), 1 / e);
  } else {
    across = std::max(std::fabs(across), std::fabs(y));
  }
  const double r = std::sqrt(x * x + y * y + z * z);
  return -std::min(a[5] - r, a[4] - std::min(across, r));
}

namespace {
/// Distance-like value of one family of woven threads of mesh1: position `u` along the weave (period
/// 2 spacing), wave `wave` of the thread's height.
double thread(double u, double spacing, double y, double wave, const double* a) {
  double r = std::fmod(u, spacing * 2);
  if (r < 0) r += spacing * 2;
  r = std::fabs(r - spacing) * a[5];
  const double h = (y + wave) * a[7];
  return -std::sqrt(h * h + r * r);
}
}  // namespace

// Mesh1: two families of threads woven over and under each other, along x and along z.
double mesh1(const double* a) {
  const double x = a[0], y = a[1], z = a[2], sx = a[3], sz = a[4], amplitude = a[6];
  const double along_z = std::cos(z * kPi / sz) * amplitude, along_x = std::cos(x * kPi / sx) * amplitude;
  double value = thread(x, sx, y, -along_z, a);
  value = std::max(thread(x - sx, sx, y, along_z, a), value);
  value = std::max(thread(z, sz, y, along_x, a), value);
  return -std::max(thread(z - sz, sz, y, -along_x, a), value);
}

}  // namespace snell::function::curves
