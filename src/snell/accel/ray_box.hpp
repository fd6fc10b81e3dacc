#pragma once
// Slab test of one ray against many boxes, with the reciprocal direction computed once per ray.
#include <cmath>

#include "snell/math/bounds.hpp"

namespace snell::accel {

class RayBox {
 public:
  explicit RayBox(const math::Ray& ray)
      : origin_(ray.origin), inverse_(1.0 / ray.direction.x, 1.0 / ray.direction.y, 1.0 / ray.direction.z) {}

  /// Entry and exit t of the ray in `box` within [t0, t1]; false when it misses. The interval is widened
  /// by 1e-12 relative so that the few ulps of error in the slab arithmetic never cull a surface point
  /// lying on the box (the robustness argument of Pharr et al., PBRT 3rd ed., section 3.9.2).
  bool enter(const math::Bounds3& box, double t0, double t1, double& entry, double& exit) const {
    for (int a = 0; a < 3; ++a) {
      double tn = (box.lo[a] - origin_[a]) * inverse_[a];
      double tf = (box.hi[a] - origin_[a]) * inverse_[a];
      if (tn > tf) std::swap(tn, tf);
      // NaN (0 * inf: origin on a slab of a parallel ray) leaves the interval unchanged, as in Bounds3::clip.
      if (tn > t0) t0 = tn;
      if (tf < t1) t1 = tf;
    }
    t0 -= std::abs(t0) * 1e-12;
    t1 += std::abs(t1) * 1e-12;
    entry = t0;
    exit = t1;
    return t0 <= t1;
  }
  bool hits(const math::Bounds3& box, double t0, double t1) const {
    double entry, exit;
    return enter(box, t0, t1, entry, exit);
  }

 private:
  math::Vec3 origin_;
  math::Vec3 inverse_;
};

}  // namespace snell::accel
