// Bounds of a quadric's inside within a box, for quadrics without mixed terms (D = E = F = 0):
//   inside = { p : sum_i q_i(p_i) + J < 0 },  q_i(t) = a_i t^2 + g_i t.
// On axis i every inside point of the box has q_i(p_i) < R_i = -J - sum_{j != i} min_{box} q_j, which is an
// interval of t when a_i > 0 (or a half-line when a_i = 0). POV-Ray confines quadrics in CSG intersections
// in the same spirit (quadric.cpp, Quadric::Compute_BBox with clip bounds); this is our own derivation.
#include <algorithm>
#include <cmath>
#include <limits>

#include "snell/geometry/quadric.hpp"

namespace snell::geometry {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// a t^2 + g t, with an infinite t giving the limit (0 coefficients contribute nothing).
double term(double a, double g, double t) {
  if (std::isinf(t)) {
    if (a != 0) return a > 0 ? kInf : -kInf;
    if (g == 0) return 0;
    return (g > 0) == (t > 0) ? kInf : -kInf;
  }
  return (a * t + g) * t;
}

/// The least value of a t^2 + g t over [lo, hi].
double least(double a, double g, double lo, double hi) {
  double m = std::min(term(a, g, lo), term(a, g, hi));
  if (a > 0) {
    const double vertex = -g / (2 * a);
    if (vertex > lo && vertex < hi) m = std::min(m, term(a, g, vertex));
  }
  return m;
}

}  // namespace

Bounds3 Quadric::inside_bounds_within(const Bounds3& box) const {
  Bounds3 r = bounds_.intersection(box);
  if (mix_ != Vec3(0) || r.empty()) return r;
  double lows[3];
  for (int j = 0; j < 3; ++j) lows[j] = least(sq_[j], lin_[j], r.lo[j], r.hi[j]);
  for (int i = 0; i < 3; ++i) {
    double rest = -j_;
    for (int j = 0; j < 3; ++j)
      if (j != i) rest -= lows[j];
    if (std::isnan(rest) || rest == kInf) continue;
    const double a = sq_[i], g = lin_[i];
    double lo = -kInf, hi = kInf;
    if (a > 0) {
      // a t^2 + g t - rest < 0 between the roots.
      const double disc = g * g + 4 * a * rest;
      if (disc < 0) return {};
      const double s = std::sqrt(disc);
      lo = (-g - s) / (2 * a);
      hi = (-g + s) / (2 * a);
    } else if (a == 0 && g != 0) {
      (g > 0 ? hi : lo) = rest / g;
    } else if (a == 0 && rest <= 0) {
      return {};  // 0 < rest fails everywhere: no inside in the box
    }
    // A margin keeps rounding of hit points on the quadric inside the box.
    if (std::isfinite(lo)) r.lo[i] = std::max(r.lo[i], lo - (1e-9 * std::fabs(lo) + 1e-12));
    if (std::isfinite(hi)) r.hi[i] = std::min(r.hi[i], hi + (1e-9 * std::fabs(hi) + 1e-12));
  }
  return r;
}

}  // namespace snell::geometry
