#include "snell/function/special_shapes.hpp"

#include <algorithm>
#include <cmath>

namespace snell::function::special {

namespace {
constexpr double kPi = 3.14159265358979323846;
double field(double strength, double value) {
  return std::clamp(strength * value, -10.0, 10.0);
}
}  // namespace

// Boy's surface, Apery's sextic form with w = 1 - z and q = x^2 + y^2, scaled by s.
double boy_surface(const double* a) {
  const double x = a[0], y = a[1], z = a[2], xx = x * x, yy = y * y, zz = z * z;
  const double w = 1 - z, q = xx + yy, root2 = std::sqrt(2.0);
  const double value =
      64 * w * w * w * zz * z - 48 * w * w * zz * (3 * xx + 3 * yy + 2 * zz) +
      12 * w * z * (27 * q * q - 24 * zz * q + 36 * root2 * y * z * (yy - 3 * xx) + 4 * zz * zz) +
      (9 * xx + 9 * yy - 2 * zz) *
          (-81 * q * q - 72 * zz * q + 108 * root2 * x * z * (xx - 3 * yy) + 4 * zz * zz);
  return field(a[3], a[4] * value);
}

// Comma: a sphere of radius r/2 at x = r/2 merged with half a torus bent round it, tapered by cos(th/2).
double comma(const double* a) {
  double x = a[0];
  const double y = a[1], z = a[2], r = a[3];
  if (x == 0 && z == 0) x = 0.0001;
  const double angle = std::atan2(z, x);
  const double around = std::sqrt((x + r * 0.25) * (x + r * 0.25) + z * z);
  double tail =
      std::cos(angle * 0.5) * r * 0.5 - std::sqrt((around - r * 0.75) * (around - r * 0.75) + y * y);
  tail = std::min(z, tail);
  const double head = r * 0.5 - std::sqrt((x - r * 0.5) * (x - r * 0.5) + z * z + y * y);
  return -std::max(tail, head);
}

// Dupin's cyclide, the quartic of POV-Ray's parameters (strength, a, b, c, d, e).
double dupin_cyclid(const double* a) {
  const double x = a[0], y = a[1], z = a[2], xx = x * x, yy = y * y, zz = z * z;
  const double pa = a[4], pb = a[5], pc = a[6], pd = a[7], e2 = a[8] * a[8];
  const double b2 = pb * pb, d2 = pd * pd;
  const double p1 = b2 - d2 - (pc + pa) * (pc + pa), p2 = b2 - d2 - (pc - pa) * (pc - pa);
  const double c2 = pc * pc, a2 = pa * pa, rr = xx + yy + zz;
  const double value =
      p1 * p2 * (xx * xx + yy * yy + zz * zz) + 2 * (p1 * p2 * (xx * yy + xx * zz + yy * zz)) +
      2 * e2 * ((-d2 - c2 + b2 + a2) * (2 * x * pc + 2 * y * pd - e2) - 4 * pd * b2 * y) * rr +
      4 * e2 * e2 * (pc * x + pd * y) * (-e2 + pd * y + pc * x) + 4 * e2 * e2 * a2 * yy + e2 * e2 * e2 * e2;
  return field(a[3], -value);
}

// Enneper's surface in implicit form. POV-Ray writes its constants 2/3, 1/4, 8/9 and 2/9 in integer
// arithmetic, where they are 0; the shape it draws is that one, so it is kept. |z| below 0.2 counts as 0.2.
double enneper(const double* a) {
  const double x = a[0], y = a[1], xx = x * x, yy = y * y, zz = a[2] * a[2];
  const double z = std::fabs(a[2]) < 0.2 ? 0.2 : a[2];  // in the divisions only, as POV-Ray
  const double u = (yy - xx) / (2 * z) + 2 * zz / 9;
  const double v = (yy - xx) / (4 * z);
  return field(a[3], -(u * u * u - 6 * v * v));
}

// Helical torus: a torus of major radius R whose tube winds round it as a helix (POV-Ray's ten
// parameters: R, turns, twist, cross-section amplitude and offset, tube radius, stretch, and three more
// shaping factors).
double helical_torus(const double* a) {
  double x = a[0];
  const double y = a[1], z = a[2];
  const double p0 = a[3], p1 = a[4], p2 = a[5], p3 = a[6], p4 = a[7], p5 = a[8], p6 = a[9], p7 = a[10],
               p8 = a[11], p9 = a[12];
  double ring = std::sqrt(x * x + z * z);
  if (x == 0 && z == 0) x = 0.000001;
  const double around = std::atan2(x, z);
  const double tube_angle = std::atan2(ring - p0, y);
  const double tube = std::sqrt((ring - p0) * (ring - p0) + y * y);
  double turn = std::fmod(around * p1 + tube_angle * p2, 2 * kPi);
  if (turn < 0) turn += 2 * kPi;
  double profile = std::atan2((turn - kPi) * p8, tube - p5);
  profile = std::cos(profile * p7 + around * p9) * p3 + p4;
  ring = p4 + p5 - p0 - ring;
  turn -= kPi;
  profile -= std::min(std::sqrt((tube - p5) * (tube - p5) + turn * turn * p6), tube + p5);
  return -std::max(ring, profile);
}

// Helix of a tube whose section (superellipse of exponent `shape`: 1 round, 0 square) may be larger than
// its major radius.
double helix2(const double* a) {
  const double turn = a[1] * a[4], c = std::cos(turn), s = std::sin(turn);
  const double dx = a[0] - a[6] * c, dz = a[2] - a[6] * s;
  const double u = dx * c + dz * s, w = -dx * s + dz * c;
  const double shape = a[8];
  double r;
  if (shape == 1) {
    r = std::sqrt(u * u + w * w);
  } else if (shape != 0) {
    const double e = 2 / shape;
    r = std::pow(std::pow(std::fabs(u), e) + std::pow(std::fabs(w), e), shape * 0.5);
  } else {
    r = std::max(std::fabs(u), std::fabs(w));
  }
  return r - a[5];
}

namespace {
/// Hexagonal cell coordinates of (x, y): folded into one sixth of a cell, (x1, y1) from the nearer of
/// the cell's centre and corner, and whether that point lies past 30 degrees.
struct HexCell {
  double x1, y1;
  bool wide;
};
HexCell hex_cell(double x, double y) {
  const double root3 = std::sqrt(3.0);
  double x1 = std::fabs(std::fmod(std::fabs(x), root3) - root3 / 2);
  double y1 = std::fabs(std::fmod(std::fabs(y), 3.0) - 1.5);
  const double x2 = root3 / 2 - x1, y2 = 1.5 - y1;
  if (x1 * x1 + y1 * y1 > x2 * x2 + y2 * y2) {
    x1 = x2;
    y1 = y2;
  }
  return {x1, y1, std::atan2(y1, x1) >= kPi / 6};
}
}  // namespace

// Distance-like value across a hexagonal tiling of the x-y plane (extruded along z): along x ...
double hex_x(const double* a) {
  const HexCell h = hex_cell(a[0], a[1]);
  return h.wide ? std::cos(kPi / 3) * h.x1 + std::sin(kPi / 3) * h.y1 : h.x1;
}

// ... and along y.
double hex_y(const double* a) {
  const HexCell h = hex_cell(a[0], a[1]);
  return h.wide ? std::fabs(-std::sin(kPi / 3) * h.x1 + std::cos(kPi / 3) * h.y1) : h.y1;
}

// A hydrogen-like orbital: r^2 exp(-r/3)(3 cos^2 th - 1) with r twice the distance from the origin.
double quantum(const double* a) {
  double x = a[0];
  const double y = a[1], z = a[2];
  if (x == 0 && z == 0) x = 1e-6;
  const double ring = std::sqrt(x * x + z * z);
  const double cos_th = std::cos(std::atan2(ring, y));
  const double r = std::sqrt(ring * ring + y * y) * 2;
  const double orbital = r * r * std::exp(-r * 0.33333333) * (3 * cos_th * cos_th - 1);
  return (orbital * orbital - 12) * -0.1;
}

}  // namespace snell::function::special
