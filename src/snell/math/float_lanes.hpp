#pragma once
// L floats in one SIMD register through GCC/Clang vector extensions, for the BVH node and triangle tests
// (geometry/float_slabs.hpp, geometry/triangle_block.hpp). Code over them is written once for a lane count
// L and built twice: L = 4 for any target (SSE2 on x86-64), and L = 8 inside with_lanes's AVX2 build where
// the processor has AVX2 (chosen at run time: CI and users' machines differ, so no -march flag).
//
// No helper takes or returns a vector by value: GCC warns (-Wpsabi) that 32-byte vectors change the ABI of
// functions built without AVX, and Clang refuses such calls from AVX2 code. Kernels use the vector
// operators, `a < b ? a : b` for min and max (one minps / maxps, with its NaN rule: the second operand
// where the comparison fails) and the reference helpers below.
#include <atomic>
#include <cstdint>
#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace snell::math::lanes {

template <int L>
struct Lanes;
template <>
struct Lanes<4> {
  using F = float __attribute__((vector_size(16)));
  using M = std::int32_t __attribute__((vector_size(16)));
};
template <>
struct Lanes<8> {
  using F = float __attribute__((vector_size(32)));
  using M = std::int32_t __attribute__((vector_size(32)));
};

#define SNELL_LANES_INLINE [[gnu::always_inline]] inline

template <class V>
SNELL_LANES_INLINE void load(V& v, const float* p) {
  std::memcpy(&v, p, sizeof v);
}
template <class V>
SNELL_LANES_INLINE void store(float* p, const V& v) {
  std::memcpy(p, &v, sizeof v);
}
/// Every lane x (-0 becomes +0). A vector plus a scalar becomes one broadcast; a loop over the lanes, or
/// x - V{}, became a chain of inserts in GCC 12's AVX2 builds.
template <class V>
SNELL_LANES_INLINE void splat(V& v, float x) {
  v = x + V{};
}

/// Bit l set where lane l of the comparison result `m` is true (all ones): movmskps per 16 bytes.
template <class M>
SNELL_LANES_INLINE unsigned bits(const M& m) {
  unsigned r = 0;
#if defined(__SSE2__)
  for (unsigned h = 0; h < sizeof m / 16; ++h) {
    __m128 q;
    std::memcpy(&q, reinterpret_cast<const char*>(&m) + 16 * h, 16);
    r |= static_cast<unsigned>(_mm_movemask_ps(q)) << (4 * h);
  }
#else
  for (unsigned l = 0; l < sizeof m / sizeof m[0]; ++l) r |= static_cast<unsigned>(m[l] != 0) << l;
#endif
  return r;
}

/// Whether with_lanes takes its AVX2 build: the processor has AVX2 and tests have not asked for the
/// portable one.
bool wide_lanes();
/// Makes with_lanes take the portable build (true) or the fastest (false), for tests of both; returns
/// whether the processor has AVX2.
bool use_portable_lanes(bool portable);

#if defined(__x86_64__) && defined(__GNUC__)
template <class F>
[[gnu::target("avx2")]] auto run_avx2(F& f) {
  return f.template operator()<8>();
}
#endif

/// f.template operator()<L>() with L = 8 in a build for AVX2 where wide_lanes(), else L = 4. `f` should
/// be always_inline (a lambda `[&]<int L>() __attribute__((always_inline)) {...}`), so that all of it is
/// built for the chosen instruction set.
template <class F>
SNELL_LANES_INLINE auto with_lanes(F&& f) {
#if defined(__x86_64__) && defined(__GNUC__)
  if (wide_lanes()) return run_avx2(f);
#endif
  return f.template operator()<4>();
}

}  // namespace snell::math::lanes
