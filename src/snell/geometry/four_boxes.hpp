#pragma once
// Slab test of one ray against the four child boxes of a wide BVH node (float corners, double arithmetic),
// two boxes per SSE2 instruction on x86-64 and a plain loop elsewhere. Results: the ray's interval in
// each box, clipped to [t_min, t_max]; empty (near > far) when it misses.
#include <array>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "snell/geometry/ray_box.hpp"

namespace snell::geometry {

inline void four_slab_tests(const RayBox& ray, const float (&lo)[3][4], const float (&hi)[3][4], double t_min,
                            double t_max, std::array<double, 4>& near_t, std::array<double, 4>& far_t) {
#if defined(__SSE2__)
  __m128d near_01 = _mm_set1_pd(t_min), near_23 = near_01;
  __m128d far_01 = _mm_set1_pd(t_max), far_23 = far_01;
  for (int a = 0; a < 3; ++a) {
    const __m128 near_plane = _mm_loadu_ps(ray.negative(a) ? hi[a] : lo[a]);
    const __m128 far_plane = _mm_loadu_ps(ray.negative(a) ? lo[a] : hi[a]);
    const __m128d origin = _mm_set1_pd(ray.origin()[a]), inverse = _mm_set1_pd(ray.inverse()[a]);
    const auto t_of = [&](__m128d plane) { return _mm_mul_pd(_mm_sub_pd(plane, origin), inverse); };
    // maxpd(x, y) is x > y ? x : y, so a NaN plane distance (0 * inf) leaves the interval as it was, as
    // in RayBox::enter; likewise minpd.
    near_01 = _mm_max_pd(t_of(_mm_cvtps_pd(near_plane)), near_01);
    near_23 = _mm_max_pd(t_of(_mm_cvtps_pd(_mm_movehl_ps(near_plane, near_plane))), near_23);
    far_01 = _mm_min_pd(t_of(_mm_cvtps_pd(far_plane)), far_01);
    far_23 = _mm_min_pd(t_of(_mm_cvtps_pd(_mm_movehl_ps(far_plane, far_plane))), far_23);
  }
  _mm_storeu_pd(&near_t[0], near_01);
  _mm_storeu_pd(&near_t[2], near_23);
  _mm_storeu_pd(&far_t[0], far_01);
  _mm_storeu_pd(&far_t[2], far_23);
#else
  near_t.fill(t_min);
  far_t.fill(t_max);
  for (int a = 0; a < 3; ++a) {
    const float* near_plane = ray.negative(a) ? hi[a] : lo[a];
    const float* far_plane = ray.negative(a) ? lo[a] : hi[a];
    const double origin = ray.origin()[a], inverse = ray.inverse()[a];
    for (int k = 0; k < 4; ++k) {
      const double tn = (near_plane[k] - origin) * inverse;
      const double tf = (far_plane[k] - origin) * inverse;
      near_t[k] = tn > near_t[k] ? tn : near_t[k];
      far_t[k] = tf < far_t[k] ? tf : far_t[k];
    }
  }
#endif
}

/// The double-precision four-box test in the shape of FloatSlabs::test, for the rays FloatSlabs cannot
/// represent: bit k set when the ray may cross box k, entry[k] where it enters (widened as RayBox::enter).
class DoubleSlabs {
 public:
  using Real = double;
  explicit DoubleSlabs(const math::Ray& ray) : ray_(ray) {}
  static double round_down(double v) { return v; }
  static double round_up(double v) { return v; }
  template <int L = 4, int W>
  int test(const float (&planes)[6][W], double t_min, double t_max, double (&entry)[W]) const {
    int mask = 0;
    for (int first = 0; first < W; first += 4) {
      // This path is rare (see FloatSlabs::usable): copying each group of four costs nothing measurable.
      float group_lo[3][4], group_hi[3][4];
      for (int a = 0; a < 3; ++a)
        for (int k = 0; k < 4; ++k) {
          group_lo[a][k] = planes[a][first + k];
          group_hi[a][k] = planes[3 + a][first + k];
        }
      std::array<double, 4> near_t, far_t;
      four_slab_tests(ray_, group_lo, group_hi, t_min, t_max, near_t, far_t);
      for (int k = 0; k < 4; ++k)
        if (RayBox::widened_overlap(near_t[k], far_t[k], entry[first + k])) mask |= 1 << (first + k);
    }
    return mask;
  }

 private:
  RayBox ray_;

 public:
  /// FloatSlabs::Lanes's interface: the ray with a window.
  template <int L>
  class Lanes {
   public:
    Lanes(const DoubleSlabs& slabs, double t_min, double t_max)
        : slabs_(slabs), t_min_(t_min), t_max_(t_max) {}
    void set_t_max(double t_max) { t_max_ = t_max; }
    template <int W>
    int test(const float (&planes)[6][W], double (&entry)[W]) const {
      return slabs_.test(planes, t_min_, t_max_, entry);
    }

   private:
    const DoubleSlabs& slabs_;
    double t_min_, t_max_;
  };
};

}  // namespace snell::geometry
