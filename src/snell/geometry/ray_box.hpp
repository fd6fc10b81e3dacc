#pragma once
// Slab test of one ray against many boxes, with the reciprocal direction computed once per ray.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "snell/math/bounds.hpp"

namespace snell::geometry {

/// The float just below finite `f` (the walk converts a double to float per hit, where std::nextafter's
/// library call showed in profiles): one step of the bit pattern, whose order follows the value's for a
/// given sign (IEEE 754).
inline float next_float_down(float f) {
  if (f == 0) return -std::numeric_limits<float>::denorm_min();
  const auto bits = std::bit_cast<uint32_t>(f);
  return std::bit_cast<float>(f > 0 ? bits - 1 : bits + 1);
}

/// The nearest float not above (below) `v`, for conversions that must stay conservative; beyond float's
/// range the infinity on that side (NaN: the infinity that makes the result useless as a bound).
inline float float_below(double v) {
  constexpr double kFloatMax = std::numeric_limits<float>::max();
  if (!(std::abs(v) <= kFloatMax)) return v > 0 ? static_cast<float>(kFloatMax) : -INFINITY;
  const auto f = static_cast<float>(v);
  return static_cast<double>(f) > v ? next_float_down(f) : f;
}
inline float float_above(double v) {
  return -float_below(-v);
}

/// float_below(v) and float_above(v) of |v| <= float's largest with one conversion: the nearest float
/// is one of them and its neighbour on the other side of v the other (the walk's setup rounds each
/// origin coordinate both ways).
inline void float_bracket(double v, float& below, float& above) {
  const auto f = static_cast<float>(v);
  const auto back = static_cast<double>(f);
  below = back > v ? next_float_down(f) : f;
  above = back < v ? -next_float_down(-f) : f;
}

/// float_above of a value that changes seldom (a walk's window end, lowered only by a hit), rounded again
/// only when it changes: per leaf, the rounding was a twentieth of a random ray's instructions.
class FloatAboveOnChange {
 public:
  explicit FloatAboveOnChange(double v) : v_(v), rounded_(float_above(v)) {}
  float operator()(double v) {
    if (v != v_) {
      v_ = v;
      rounded_ = float_above(v);
    }
    return rounded_;
  }

 private:
  double v_;
  float rounded_;
};

/// `b` grown by 2^-40 of its magnitude: bounds are computed in double from exact shape boxes, and that
/// (thousands of ulps) absorbs their rounding, so that culling by the box never drops a hit the double
/// test finds, without making boxes measurably larger.
inline math::Bounds3 padded(const math::Bounds3& b) {
  const double magnitude = std::max(max_component(math::abs(b.lo)), max_component(math::abs(b.hi)));
  const double pad = magnitude * 0x1p-40 + 1e-300;
  return {b.lo - math::Vec3(pad), b.hi + math::Vec3(pad)};
}

/// A box in float, rounded outward so that it contains the double box it was made from: half the memory
/// of a Bounds3 (more nodes per cache line).
struct FloatBox {
  float lo[3] = {0, 0, 0};
  float hi[3] = {0, 0, 0};

  FloatBox() = default;
  /// The box no ray enters: lo = +inf, hi = -inf on every axis.
  static FloatBox nothing() {
    FloatBox b;
    for (int a = 0; a < 3; ++a) {
      b.lo[a] = INFINITY;
      b.hi[a] = -INFINITY;
    }
    return b;
  }
  explicit FloatBox(const math::Bounds3& b) {
    for (int a = 0; a < 3; ++a) {
      lo[a] = float_below(b.lo[a]);
      hi[a] = float_above(b.hi[a]);
    }
  }
};

class RayBox {
 public:
  explicit RayBox(const math::Ray& ray)
      : origin_(ray.origin),
        inverse_(1.0 / ray.direction.x, 1.0 / ray.direction.y, 1.0 / ray.direction.z),
        negative_{std::signbit(ray.direction.x), std::signbit(ray.direction.y),
                  std::signbit(ray.direction.z)} {}

  /// Entry and exit t of the ray in `box` within [t0, t1]; false when it misses. The interval is widened
  /// by 1e-12 relative so that the few ulps of error in the slab arithmetic never cull a surface point
  /// lying on the box (the robustness argument of Pharr et al., PBRT 3rd ed., section 3.9.2).
  bool enter(const math::Bounds3& box, double t0, double t1, double& entry, double& exit) const {
    return enter(box.lo.x, box.lo.y, box.lo.z, box.hi.x, box.hi.y, box.hi.z, t0, t1, entry, exit);
  }
  bool enter(const FloatBox& box, double t0, double t1, double& entry, double& exit) const {
    return enter(box.lo[0], box.lo[1], box.lo[2], box.hi[0], box.hi[1], box.hi[2], t0, t1, entry, exit);
  }
  bool hits(const math::Bounds3& box, double t0, double t1) const {
    double entry, exit;
    return enter(box, t0, t1, entry, exit);
  }
  bool negative(int axis) const { return negative_[axis]; }
  const math::Vec3& origin() const { return origin_; }
  const math::Vec3& inverse() const { return inverse_; }
  /// The 1e-12 relative widening of `enter`, for callers that run the slab arithmetic themselves.
  static bool widened_overlap(double t0, double t1, double& entry) {
    entry = t0 - std::abs(t0) * 1e-12;
    return entry <= t1 + std::abs(t1) * 1e-12;
  }

  bool enter(double lo_x, double lo_y, double lo_z, double hi_x, double hi_y, double hi_z, double t0,
             double t1, double& entry, double& exit) const {
    // The near plane of each slab is known from the direction's sign, so no swap is needed. NaN (0 * inf:
    // origin on a slab of a parallel ray) fails both comparisons and leaves the interval unchanged, as in
    // Bounds3::clip.
    const auto slab = [&](double lo, double hi, double origin, double inverse, bool negative) {
      const double tn = ((negative ? hi : lo) - origin) * inverse;
      const double tf = ((negative ? lo : hi) - origin) * inverse;
      t0 = tn > t0 ? tn : t0;
      t1 = tf < t1 ? tf : t1;
    };
    slab(lo_x, hi_x, origin_.x, inverse_.x, negative_[0]);
    slab(lo_y, hi_y, origin_.y, inverse_.y, negative_[1]);
    slab(lo_z, hi_z, origin_.z, inverse_.z, negative_[2]);
    entry = t0 - std::abs(t0) * 1e-12;
    exit = t1 + std::abs(t1) * 1e-12;
    return entry <= exit;
  }

 private:
  math::Vec3 origin_;
  math::Vec3 inverse_;
  bool negative_[3];
};

}  // namespace snell::geometry
