#pragma once
// sin, cos, atan2 and sqrt at kLaneWidth points at once, for the register code's multi-point evaluation
// (an isosurface's march samples several points of a ray in one pass). Branch-free vector code: both
// polynomials of a quadrant are computed and the right one selected, so unlike a scalar kernel there are
// no mispredicted branches on the march's scattered arguments. Within about two units in the last place of
// glibc (the unit test compares over many arguments); arguments outside the kernels' range (|x| > 1e6 for
// sin and cos, zeros, infinities and NaNs for atan2) go to libm lane by lane. Scalar calls keep libm.
//
// The polynomials are Cephes's (S. L. Moshier, "Methods and Programs for Mathematical Functions", 1989):
// sin and cos on [-pi/4, pi/4] after reduction by pi/2 in three parts, atan on [0, tan(pi/8)] after
// reduction by pi/4 and pi/2. Plain IEEE operations in a fixed order (no fused multiply-add), so every
// build of the kernels, SSE2 or AVX2, gives the same bits.
#include <cstddef>

namespace snell::function::lanes {

inline constexpr std::size_t kLaneWidth = 8;

/// out[l] = sin(x[l]) for l < kLaneWidth.
void sin(const double* x, double* out);
/// out[l] = cos(x[l]).
void cos(const double* x, double* out);
/// out[l] = atan2(y[l], x[l]).
void atan2(const double* y, const double* x, double* out);
/// out[l] = sqrt(x[l]) (correctly rounded, as std::sqrt).
void sqrt(const double* x, double* out);

/// For tests: with `portable`, the SSE2 build of the kernels even where AVX2 is present; returns whether
/// the processor has AVX2. Not for use while other threads evaluate functions.
bool use_portable_kernels(bool portable);

}  // namespace snell::function::lanes
