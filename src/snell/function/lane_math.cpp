#include "snell/function/lane_math.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>

#include "snell/math/cpu.hpp"
#include "snell/math/simd.hpp"

#if defined(__x86_64__)
#include <immintrin.h>
#endif

// The kernels are written once over vector extensions of W doubles (math/simd.hpp) and built twice: W = 2
// for any x86-64 (SSE2), W = 4 in functions compiled for AVX2, chosen once at run time.
namespace snell::function::lanes {

namespace {

using math::simd::abs;
using math::simd::any;
using math::simd::bits;
using math::simd::kSignBit;
using math::simd::load;
using math::simd::select;
using math::simd::store;
using math::simd::Vec;

// pi/2 = kPio2a + kPio2b + kPio2c: Cephes's three-part pi/4 doubled (exact); the first two have short
// significands, so n * kPio2a and n * kPio2b are exact for |n| < 2^29.
constexpr double kPio2a = 2 * 7.85398125648498535156E-1;
constexpr double kPio2b = 2 * 3.77489470793079817668E-8;
constexpr double kPio2c = 2 * 2.69515142907905952645E-15;
constexpr double kTwoOverPi = 0.63661977236758134308;
constexpr double kRoundShift = 6755399441055744.0;  // 1.5 * 2^52: adding it rounds to an integer
constexpr double kTrigLimit = 1e6;                  // larger arguments: libm

/// out = sin(in) for quarter offset 0, cos(in) for offset 1 (cos x = sin(x + pi/2)), W lanes.
template <int W>
SNELL_SIMD_INLINE void trig_chunk(const double* in, double* out, std::int64_t offset) {
  using V = typename Vec<W>::V;
  using M = typename Vec<W>::M;
  const V x = load<V>(in);
  const V shifted = x * kTwoOverPi + kRoundShift;
  const V n = shifted - kRoundShift;                         // x / (pi/2), rounded to the nearest integer
  const M quadrant = bits<M>(shifted) + offset;              // low bits of n (two's complement), plus offset
  const V r = ((x - n * kPio2a) - n * kPio2b) - n * kPio2c;  // |r| <= pi/4
  const V z = r * r;
  const V s =
      r +
      r * z *
          (((((1.58962301576546568060E-10 * z - 2.50507477628578072866E-8) * z + 2.75573136213857245213E-6) *
                 z -
             1.98412698295895385996E-4) *
                z +
            8.33333333332211858878E-3) *
               z -
           1.66666666666666307295E-1);
  const V c =
      1.0 - 0.5 * z +
      z * z *
          (((((-1.13585365213876817300E-11 * z + 2.08757008419747316778E-9) * z - 2.75573141792967388112E-7) *
                 z +
             2.48015872888517045348E-5) *
                z -
            1.38888888888730564116E-3) *
               z +
           4.16666666666665929218E-2);
  const M odd = -(quadrant & 1);  // all ones in odd quadrants, where sin follows the cosine polynomial
  const V value = (V)((M)select(odd, c, s) ^ ((quadrant << 62) & kSignBit));  // quadrants 2, 3: negated
  store(out, offset == 0 ? select(x == V{}, x, value) : value);               // sin(-0) = -0
}

template <int W>
SNELL_SIMD_INLINE bool trig_in_range(const double* in) {
  using V = typename Vec<W>::V;
  using M = typename Vec<W>::M;
  const V x = load<V>(in);
  const V limit = V{} + kTrigLimit;
  return !any<W>(~(abs<V, M>(x) <= limit));  // NaN compares false: out of range
}

constexpr double kPi = 3.14159265358979323846;
constexpr double kPio2 = 1.57079632679489661923;
constexpr double kPio4 = 7.85398163397448309616E-1;
constexpr double kMoreBits = 6.123233995736765886130E-17;  // pi/2 - kPio2
constexpr double kTan3Pi8 = 2.41421356237309504880;

/// out = atan2(y, x), W lanes; returns false where some lane needs libm (zeros, huge or tiny values).
template <int W>
SNELL_SIMD_INLINE bool atan2_chunk(const double* y_in, const double* x_in, double* out) {
  using V = typename Vec<W>::V;
  using M = typename Vec<W>::M;
  const V y = load<V>(y_in), x = load<V>(x_in);
  const V zero = V{}, one = zero + 1.0;
  const V ratio = y / x;
  const V a = abs<V, M>(ratio);
  // atan(a) by Cephes's reduction: a > tan(3pi/8): pi/2 + atan(-1/a); a > 0.66: pi/4 + atan((a-1)/(a+1)).
  const M big = a > zero + kTan3Pi8;
  const M middle = (a > zero + 0.66) & ~big;
  const V w =
      select(big, zero - 1.0, select(middle, a - 1.0, a)) / select(big, a, select(middle, a + 1.0, one));
  const V base = select(big, zero + kPio2, select(middle, zero + kPio4, zero));
  const V more = select(big, zero + kMoreBits, select(middle, zero + 0.5 * kMoreBits, zero));
  const V z = w * w;
  const V p =
      z *
      ((((-8.750608600031904122785E-1 * z - 1.615753718733365076637E1) * z - 7.500855792314704667340E1) * z -
        1.228866684490136173410E2) *
           z -
       6.485021904942025371773E1);
  const V q =
      ((((z + 2.485846490142306297962E1) * z + 1.650270098316988542046E2) * z + 4.328810604912902668951E2) *
           z +
       4.853903996359136964868E2) *
          z +
      1.945506571482613964425E2;
  const V t = w * (p / q) + w + more;
  const V magnitude = base + t;
  const V angle = (V)((M)magnitude ^ ((M)ratio & kSignBit));  // atan(y / x)
  // x < 0: the angle is across the y axis, pi away (Cephes: -pi below the x axis).
  const V turn = select(x < zero, select(y < zero, zero - kPi, zero + kPi), zero);
  store(out, turn + angle);
  const V huge = zero + 1e300, tiny = zero + 1e-290;
  const M ordinary = (abs<V, M>(x) < huge) & (abs<V, M>(y) < huge) & (a > tiny) & (a < zero + 1e290);
  return !any<W>(~ordinary);
}

// Whole registers of kLaneWidth lanes, for each build.
template <int W>
SNELL_SIMD_INLINE bool sin_all(const double* x, double* out, std::int64_t offset) {
  bool ok = true;
  for (std::size_t l = 0; l < kLaneWidth; l += W) {
    trig_chunk<W>(x + l, out + l, offset);
    ok = trig_in_range<W>(x + l) && ok;
  }
  return ok;
}

template <int W>
SNELL_SIMD_INLINE bool atan2_all(const double* y, const double* x, double* out) {
  bool ok = true;
  for (std::size_t l = 0; l < kLaneWidth; l += W) ok = atan2_chunk<W>(y + l, x + l, out + l) && ok;
  return ok;
}

bool sin_sse2(const double* x, double* out, std::int64_t offset) {
  return sin_all<2>(x, out, offset);
}
bool atan2_sse2(const double* y, const double* x, double* out) {
  return atan2_all<2>(y, x, out);
}
// The vector extensions have no square root, and std::sqrt keeps errno, so not even a loop of it becomes
// one vector instruction: the intrinsics.
void sqrt_sse2(const double* x, double* out) {
#if defined(__x86_64__)
  for (std::size_t l = 0; l < kLaneWidth; l += 2) _mm_storeu_pd(out + l, _mm_sqrt_pd(_mm_loadu_pd(x + l)));
#else
  for (std::size_t l = 0; l < kLaneWidth; ++l) out[l] = std::sqrt(x[l]);
#endif
}

#if defined(__x86_64__) && defined(__GNUC__)
#define SNELL_LANE_AVX2 1
[[gnu::target("avx2")]] bool sin_avx2(const double* x, double* out, std::int64_t offset) {
  return sin_all<4>(x, out, offset);
}
[[gnu::target("avx2")]] bool atan2_avx2(const double* y, const double* x, double* out) {
  return atan2_all<4>(y, x, out);
}
[[gnu::target("avx2")]] void sqrt_avx2(const double* x, double* out) {
  for (std::size_t l = 0; l < kLaneWidth; l += 4)
    _mm256_storeu_pd(out + l, _mm256_sqrt_pd(_mm256_loadu_pd(x + l)));
}
#endif

struct Kernels {
  bool (*sin)(const double*, double*, std::int64_t) = sin_sse2;
  bool (*atan2)(const double*, const double*, double*) = atan2_sse2;
  void (*sqrt)(const double*, double*) = sqrt_sse2;
};

bool has_avx2() {
#if defined(SNELL_LANE_AVX2)
  return math::has_avx2();
#else
  return false;
#endif
}

Kernels choose(bool portable) {
  Kernels k;
#if defined(SNELL_LANE_AVX2)
  if (!portable && has_avx2()) k = {sin_avx2, atan2_avx2, sqrt_avx2};
#endif
  return k;
}

Kernels kKernels = choose(false);

template <typename Scalar>
void trig(const double* x, double* out, std::int64_t offset, Scalar scalar) {
  if (kKernels.sin(x, out, offset)) return;
  for (std::size_t l = 0; l < kLaneWidth; ++l)
    if (!(std::fabs(x[l]) <= kTrigLimit)) out[l] = scalar(x[l]);
}

}  // namespace

void sin(const double* x, double* out) {
  trig(x, out, 0, [](double a) { return std::sin(a); });
}

void cos(const double* x, double* out) {
  trig(x, out, 1, [](double a) { return std::cos(a); });
}

void atan2(const double* y, const double* x, double* out) {
  if (kKernels.atan2(y, x, out)) return;
  // Zeros (signed results), infinities, NaNs and ratios near the ends of the range: libm, lane by lane.
  for (std::size_t l = 0; l < kLaneWidth; ++l) {
    const double a = std::fabs(y[l] / x[l]);
    if (!(std::fabs(x[l]) < 1e300 && std::fabs(y[l]) < 1e300 && a > 1e-290 && a < 1e290))
      out[l] = std::atan2(y[l], x[l]);
  }
}

void sqrt(const double* x, double* out) {
  kKernels.sqrt(x, out);
}

bool use_portable_kernels(bool portable) {
  kKernels = choose(portable);
  return has_avx2();
}

}  // namespace snell::function::lanes
