#pragma once
// Small helpers over GCC/Clang vector extensions of W doubles, for kernels written once and built twice:
// W = 2 for any x86-64 (SSE2), W = 4 in functions compiled for AVX2 and chosen at run time (the function
// lane kernels, lane_math.cpp, and the multi-point noise, povray_noise.cpp). Only operations both
// instruction sets have natively (double compares, 64-bit adds, shifts and logic, no 64-bit integer
// compares) and no fused multiply-add, so both builds give the same bits. The helpers take vectors by
// value; they are inlined into their callers, so GCC's ABI note about such arguments does not apply
// (files using them are compiled with -Wno-psabi, CMakeLists.txt).
#include <cstdint>
#include <cstring>

namespace snell::math::simd {

// W doubles (V), W 64-bit integers for masks and bits (M) and W 32-bit integers (I). Spelled out per
// width: GCC drops a vector_size attribute whose size depends on a template parameter.
template <int W>
struct Vec;
template <>
struct Vec<2> {
  using V = double __attribute__((vector_size(16)));
  using M = std::int64_t __attribute__((vector_size(16)));
  using I = std::int32_t __attribute__((vector_size(8)));
};
template <>
struct Vec<4> {
  using V = double __attribute__((vector_size(32)));
  using M = std::int64_t __attribute__((vector_size(32)));
  using I = std::int32_t __attribute__((vector_size(16)));
};

inline constexpr std::int64_t kSignBit = INT64_MIN;

#define SNELL_SIMD_INLINE [[gnu::always_inline]] inline

template <typename V>
SNELL_SIMD_INLINE V load(const double* p) {
  V v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

template <typename V>
SNELL_SIMD_INLINE void store(double* p, V v) {
  std::memcpy(p, &v, sizeof v);
}

// Same-size vector casts reinterpret the bits.
template <typename M, typename V>
SNELL_SIMD_INLINE M bits(V v) {
  return (M)v;
}

/// Lanes of a where mask m is set (all ones), else lanes of b.
template <typename V, typename M>
SNELL_SIMD_INLINE V select(M m, V a, V b) {
  return (V)(((M)a & m) | ((M)b & ~m));
}

template <typename V, typename M>
SNELL_SIMD_INLINE V abs(V v) {
  return (V)((M)v & ~kSignBit);
}

template <int W, typename M>
SNELL_SIMD_INLINE bool any(M m) {
  std::int64_t seen = 0;
  for (int l = 0; l < W; ++l) seen |= m[l];
  return seen != 0;
}

/// Bit l set where lane l of mask m is set.
template <int W, typename M>
SNELL_SIMD_INLINE std::uint32_t mask_bits(M m) {
#if defined(__x86_64__)
  // One instruction (movmskpd: the lanes' sign bits, which a mask's lanes have where set).
  if constexpr (W == 2) return static_cast<std::uint32_t>(__builtin_ia32_movmskpd((typename Vec<2>::V)m));
#endif
  std::uint32_t out = 0;
  for (int l = 0; l < W; ++l) out |= static_cast<std::uint32_t>(m[l] & 1) << l;
  return out;
}

}  // namespace snell::math::simd
