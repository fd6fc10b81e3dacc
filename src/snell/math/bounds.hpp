#pragma once
#include "snell/math/constants.hpp"
#include "snell/math/ray.hpp"
#include "snell/math/vec3.hpp"

namespace snell::math {

/// Axis-aligned box. Default constructed it is empty (min > max), so `unite` from empty works.
struct Bounds3 {
  Vec3 lo{kInfinity};
  Vec3 hi{-kInfinity};

  constexpr Bounds3() = default;
  constexpr Bounds3(const Vec3& a, const Vec3& b) : lo(min(a, b)), hi(max(a, b)) {}

  static Bounds3 infinite() { return {Vec3(-kInfinity), Vec3(kInfinity)}; }

  constexpr bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
  bool is_finite() const { return math::is_finite(lo) && math::is_finite(hi); }
  constexpr Vec3 center() const { return 0.5 * (lo + hi); }
  constexpr Vec3 extent() const { return hi - lo; }
  constexpr bool contains(const Vec3& p) const {
    return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z && p.z <= hi.z;
  }
  constexpr Bounds3& unite(const Vec3& p) {
    lo = min(lo, p);
    hi = max(hi, p);
    return *this;
  }
  constexpr Bounds3& unite(const Bounds3& b) {
    lo = min(lo, b.lo);
    hi = max(hi, b.hi);
    return *this;
  }
  constexpr Bounds3 intersection(const Bounds3& b) const {
    Bounds3 r;
    r.lo = max(lo, b.lo);
    r.hi = min(hi, b.hi);
    return r;
  }
  double surface_area() const {
    if (empty()) return 0;
    const Vec3 e = extent();
    return 2 * (e.x * e.y + e.y * e.z + e.z * e.x);
  }

  /// Slab test; on success narrows [t0, t1] to the part of the ray inside the box.
  bool clip(const Ray& ray, double& t0, double& t1) const {
    for (int a = 0; a < 3; ++a) {
      const double inv = 1.0 / ray.direction[a];
      double tn = (lo[a] - ray.origin[a]) * inv;
      double tf = (hi[a] - ray.origin[a]) * inv;
      if (tn > tf) std::swap(tn, tf);
      // NaN (0 * inf when the origin lies on a slab of a parallel ray) must not reject the ray.
      if (tn > t0) t0 = tn;
      if (tf < t1) t1 = tf;
      if (t0 > t1) return false;
    }
    return true;
  }
};

}  // namespace snell::math
