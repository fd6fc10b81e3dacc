#pragma once
// Slab test of one ray against the float child boxes of a wide BVH node in single precision, L boxes per
// instruction (math/float_lanes.hpp: four with SSE2, eight with AVX2), and conservative: a box the exact ray
// meets within [t_min, t_max] is never reported as missed.
//
// Why it is conservative (the argument of Ize, "Robust BVH Ray Traversal", JCGT 2(2), 2013, adapted):
//  - The box corners are floats already rounded outward (FloatBox), so they are exact here.
//  - The ray origin is rounded per axis and per plane in the direction that can only enlarge the interval:
//    the near planes are measured from the origin rounded forward along the ray, the far planes from the
//    origin rounded backward. The exact distances N (near) and F (far) so measured satisfy
//    N <= N_exact and F >= F_exact.
//  - Each computed distance then carries at most three roundings (the subtraction, the reciprocal of the
//    direction rounded to float, the product), a relative error below gamma_3 = 3u / (1 - 3u), u = 2^-24.
//    Widening the clipped interval by kRelativeSlack of its ends' magnitudes (kRelativeSlack > gamma_3)
//    therefore gives near <= N and far >= F, so a box the exact ray meets is kept, and `entry` never lies
//    beyond the exact entry, so culling a pending child by the nearest hit is safe.
//  - The window starts at t_min >= 0, so near >= 0 and the widening is one product per end: near scaled by
//    1 - kRelativeSlack, far by 1 + kRelativeSlack (a negative far only moves further below near; an
//    infinite end stays infinite). Walks with t_min < 0 take the double-precision test.
// Rays this cannot represent (origins beyond 1e30, or direction components so small that their
// reciprocal overflows a float) are reported by `usable()` and walked with the double-precision test.
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "snell/geometry/ray_box.hpp"
#include "snell/math/float_lanes.hpp"
#include "snell/math/ray.hpp"

namespace snell::geometry {

class FloatSlabs {
 public:
  /// Relative widening of each interval end: above gamma_3 for u = 2^-24 (about 1.8e-7), with room for
  /// the double-to-float rounding of the reciprocal.
  static constexpr float kRelativeSlack = 1e-6f;

  explicit FloatSlabs(const math::Ray& ray) {
    for (int a = 0; a < 3; ++a) {
      const double o = ray.origin[a], d = ray.direction[a];
      const bool negative = std::signbit(d);
      const double inverse = 1.0 / d;
      // d == 0 gives an infinite reciprocal, which the NaN rule below handles; a tiny non-zero d whose
      // reciprocal overflows float would turn a finite distance infinite, so such rays take the double walk.
      if (!(std::abs(o) < 1e30) || (d != 0 && !(std::abs(inverse) < 1e30))) {
        usable_ = false;
        return;
      }
      inverse_[a] = static_cast<float>(inverse);
      // Along the ray the origin moves towards +axis when d >= 0: the forward-rounded origin is then the
      // one rounded up.
      float below, above;
      float_bracket(o, below, above);
      near_origin_[a] = negative ? below : above;
      far_origin_[a] = negative ? above : below;
      // The rows of a box array (lo x, y, z, then hi x, y, z) holding the near and far planes for this
      // direction, chosen once per ray rather than per node (as Embree's nearX / farX).
      near_row_[a] = negative ? 3 + a : a;
      far_row_[a] = negative ? a : 3 + a;
    }
  }

  bool usable() const { return usable_; }

  /// For the BVH walk: distances are floats, and doubles convert to them conservatively.
  using Real = float;
  static float round_down(double v) { return float_below(v); }
  static float round_up(double v) { return float_above(v); }

  /// Bit k of the result is set when the ray may cross box k of `planes` (rows 0-2: lo x, y, z; rows 3-5:
  /// hi) within [t_min, t_max], 0 <= t_min; entry[k] is then a lower bound of where it enters. L boxes per
  /// instruction.
  template <int L = 4, int N>
  SNELL_LANES_INLINE int test(const float (&planes)[6][N], float t_min, float t_max,
                              float (&entry)[N]) const {
    return Lanes<L>(*this, t_min, t_max).test(planes, entry);
  }

  /// The ray's values spread over L lanes once, with a window: a walk that tests many nodes then loads
  /// them instead of broadcasting nine scalars per node (a third of a node test's instructions).
  template <int L>
  class Lanes {
   public:
    using F = typename math::lanes::Lanes<L>::F;
    using M = typename math::lanes::Lanes<L>::M;

    SNELL_LANES_INLINE Lanes(const FloatSlabs& slabs, float t_min, float t_max) {
      using math::lanes::splat;
      for (int a = 0; a < 3; ++a) {
        splat(near_origin_[a], slabs.near_origin_[a]);
        splat(far_origin_[a], slabs.far_origin_[a]);
        splat(inverse_[a], slabs.inverse_[a]);
        near_row_[a] = slabs.near_row_[a];
        far_row_[a] = slabs.far_row_[a];
        near_offset_[a] = near_row_[a] * static_cast<std::ptrdiff_t>(sizeof(float[kOffsetWidth]));
        far_offset_[a] = far_row_[a] * static_cast<std::ptrdiff_t>(sizeof(float[kOffsetWidth]));
      }
      splat(t_min_, t_min);
      splat(t_max_, t_max);
    }
    SNELL_LANES_INLINE void set_t_max(float t_max) { math::lanes::splat(t_max_, t_max); }

    /// FloatSlabs::test over the window held.
    template <int N>
    SNELL_LANES_INLINE int test(const float (&planes)[6][N], float (&entry)[N]) const {
      static_assert(N % L == 0, "boxes come in groups of L");
      using math::lanes::load;
      int mask = 0;
      for (int first = 0; first < N; first += L) {
        F near = t_min_, far = t_max_;
        for (int a = 0; a < 3; ++a) {
          F near_plane, far_plane;
          if constexpr (N == kOffsetWidth) {
            const char* rows = reinterpret_cast<const char*>(planes);
            load(near_plane, reinterpret_cast<const float*>(rows + near_offset_[a]) + first);
            load(far_plane, reinterpret_cast<const float*>(rows + far_offset_[a]) + first);
          } else {
            load(near_plane, planes[near_row_[a]] + first);
            load(far_plane, planes[far_row_[a]] + first);
          }
          // x > y ? x : y (maxps), so a NaN distance (0 * inf: the origin on a slab plane of a ray parallel
          // to it) leaves the interval as it was; likewise the minimum.
          const F tn = (near_plane - near_origin_[a]) * inverse_[a];
          const F tf = (far_plane - far_origin_[a]) * inverse_[a];
          near = tn > near ? tn : near;
          far = tf < far ? tf : far;
        }
        near *= 1 - kRelativeSlack;
        far *= 1 + kRelativeSlack;
        math::lanes::store(entry + first, near);
        const M kept = near <= far;
        mask |= static_cast<int>(math::lanes::bits(kept)) << first;
      }
      return mask;
    }

   private:
    F near_origin_[3], far_origin_[3], inverse_[3];
    F t_min_, t_max_;
    int near_row_[3], far_row_[3];
    /// For rows of kOffsetWidth boxes (a wide BVH node's), the rows' byte offsets, pointer-sized: a node
    /// test then adds them to the node's address as they are, where a row index took a sign extension and
    /// a shift for each of the six rows (a tenth of the test's instructions).
    static constexpr int kOffsetWidth = 8;
    std::ptrdiff_t near_offset_[3], far_offset_[3];
  };

 private:
  float near_origin_[3] = {};
  float far_origin_[3] = {};
  float inverse_[3] = {};
  int near_row_[3] = {0, 1, 2};
  int far_row_[3] = {3, 4, 5};
  bool usable_ = true;
};

}  // namespace snell::geometry
