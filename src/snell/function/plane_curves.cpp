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

}  // namespace snell::function::curves
