#include "snell/accel/box_lanes.hpp"

#include "snell/math/cpu.hpp"
#include "snell/math/simd.hpp"

namespace snell::accel {

namespace {

namespace simd = math::simd;

/// RayBox::enter on W boxes from `lo`/`hi` (per axis arrays, offset to the chunk's first box).
template <int W>
SNELL_SIMD_INLINE std::uint32_t enter_lanes(const geometry::RayBox& r, const double* const* lo,
                                            const double* const* hi, double t0_in, double t1_in) {
  using V = typename simd::Vec<W>::V;
  using M = typename simd::Vec<W>::M;
  const V zero{};
  V t0 = zero + t0_in, t1 = zero + t1_in;
  for (int a = 0; a < 3; ++a) {
    const bool negative = r.negative(a);
    const V near = simd::load<V>(negative ? hi[a] : lo[a]), far = simd::load<V>(negative ? lo[a] : hi[a]);
    const double origin = r.origin()[a], inverse = r.inverse()[a];
    const V tn = (near - origin) * inverse, tf = (far - origin) * inverse;
    // As RayBox::enter: NaN fails both comparisons and leaves the interval unchanged.
    t0 = simd::select((M)(tn > t0), tn, t0);
    t1 = simd::select((M)(tf < t1), tf, t1);
  }
  const V entry = t0 - simd::abs<V, M>(t0) * 1e-12, exit = t1 + simd::abs<V, M>(t1) * 1e-12;
  return simd::mask_bits<W>((M)(entry <= exit));
}

#if defined(__x86_64__) && defined(__GNUC__)
[[gnu::target("avx2")]] std::uint32_t enter_avx2(const geometry::RayBox& r, const double* const* lo,
                                                 const double* const* hi, double t0, double t1) {
  return enter_lanes<4>(r, lo, hi, t0, t1);
}
#endif

}  // namespace

BoxLanes::BoxLanes(const std::vector<math::Bounds3>& boxes) {
  const size_t n = (boxes.size() + kChunk - 1) / kChunk * kChunk;
  for (int a = 0; a < 3; ++a) {
    // Padding boxes run from +inf to -inf: every ray's interval on them is empty.
    lo_[a].assign(n, math::kInfinity);
    hi_[a].assign(n, -math::kInfinity);
    for (size_t i = 0; i < boxes.size(); ++i) {
      lo_[a][i] = boxes[i].lo[a];
      hi_[a][i] = boxes[i].hi[a];
    }
  }
}

std::uint32_t BoxLanes::entered(const geometry::RayBox& ray_box, size_t chunk, double t0, double t1) const {
  const size_t first = chunk * kChunk;
  const double* lo[3] = {lo_[0].data() + first, lo_[1].data() + first, lo_[2].data() + first};
  const double* hi[3] = {hi_[0].data() + first, hi_[1].data() + first, hi_[2].data() + first};
#if defined(__x86_64__) && defined(__GNUC__)
  static const bool avx2 = math::has_avx2();
  if (avx2) return enter_avx2(ray_box, lo, hi, t0, t1);
#endif
  const double* lo_half[3] = {lo[0] + 2, lo[1] + 2, lo[2] + 2};
  const double* hi_half[3] = {hi[0] + 2, hi[1] + 2, hi[2] + 2};
  return enter_lanes<2>(ray_box, lo, hi, t0, t1) | enter_lanes<2>(ray_box, lo_half, hi_half, t0, t1) << 2;
}

}  // namespace snell::accel
