#pragma once
// Slab test of one ray against the four float child boxes of a wide BVH node in single precision, four
// boxes per SSE instruction, and conservative: a box the exact ray meets within [t_min, t_max] is never
// reported as missed.
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
// Rays this cannot represent (origins beyond 1e30, or direction components so small that their
// reciprocal overflows a float) are reported by `usable()` and walked with the double-precision test.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "snell/accel/ray_box.hpp"
#include "snell/math/ray.hpp"

namespace snell::accel {

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
      near_origin_[a] = negative ? round_down(o) : round_up(o);
      far_origin_[a] = negative ? round_up(o) : round_down(o);
      // Offsets (in floats) of the near and far planes in a node's lo/hi rows for this direction.
      near_row_[a] = negative;
    }
  }

  bool usable() const { return usable_; }

  /// For the BVH walk: distances are floats, and doubles convert to them conservatively.
  using Real = float;
  static float round_down(double v) { return float_below(v); }
  static float round_up(double v) { return float_above(v); }

  /// Bit k of the result is set when the ray may cross box k of `lo`/`hi` (corners as [axis][box]) within
  /// [t_min, t_max]; entry[k] is then a lower bound of where it enters.
  template <int W>
  int test(const float (&lo)[3][W], const float (&hi)[3][W], float t_min, float t_max,
           float (&entry)[W]) const {
    static_assert(W % 4 == 0, "boxes come in groups of four");
    int mask = 0;
    for (int first = 0; first < W; first += 4) mask |= test_four(lo, hi, first, t_min, t_max, entry) << first;
    return mask;
  }

 private:
  /// Boxes first to first + 3.
  template <int W>
  int test_four(const float (&lo)[3][W], const float (&hi)[3][W], int first, float t_min, float t_max,
                float (&entry)[W]) const {
#if defined(__SSE2__)
    __m128 near = _mm_set1_ps(t_min), far = _mm_set1_ps(t_max);
    for (int a = 0; a < 3; ++a) {
      const __m128 near_plane = _mm_load_ps((near_row_[a] ? hi[a] : lo[a]) + first);
      const __m128 far_plane = _mm_load_ps((near_row_[a] ? lo[a] : hi[a]) + first);
      const __m128 inverse = _mm_set1_ps(inverse_[a]);
      // maxps(x, y) is x > y ? x : y, so a NaN distance (0 * inf: the origin on a slab plane of a ray
      // parallel to it) leaves the interval as it was; likewise minps.
      near = _mm_max_ps(_mm_mul_ps(_mm_sub_ps(near_plane, _mm_set1_ps(near_origin_[a])), inverse), near);
      far = _mm_min_ps(_mm_mul_ps(_mm_sub_ps(far_plane, _mm_set1_ps(far_origin_[a])), inverse), far);
    }
    const __m128 sign = _mm_set1_ps(-0.0f), slack = _mm_set1_ps(kRelativeSlack);
    near = _mm_sub_ps(near, _mm_mul_ps(_mm_andnot_ps(sign, near), slack));
    far = _mm_add_ps(far, _mm_mul_ps(_mm_andnot_ps(sign, far), slack));
    _mm_storeu_ps(entry + first, near);
    // An infinite end widened by infinity is NaN, which fails the comparison: such a box is truly missed.
    return _mm_movemask_ps(_mm_cmple_ps(near, far));
#else
    int mask = 0;
    for (int k = first; k < first + 4; ++k) {
      float near = t_min, far = t_max;
      for (int a = 0; a < 3; ++a) {
        const float tn = ((near_row_[a] ? hi[a][k] : lo[a][k]) - near_origin_[a]) * inverse_[a];
        const float tf = ((near_row_[a] ? lo[a][k] : hi[a][k]) - far_origin_[a]) * inverse_[a];
        near = tn > near ? tn : near;
        far = tf < far ? tf : far;
      }
      near -= std::abs(near) * kRelativeSlack;
      far += std::abs(far) * kRelativeSlack;
      entry[k] = near;
      if (near <= far) mask |= 1 << (k - first);
    }
    return mask;
#endif
  }

  float near_origin_[3] = {};
  float far_origin_[3] = {};
  float inverse_[3] = {};
  bool near_row_[3] = {};
  bool usable_ = true;
};

}  // namespace snell::accel
