#pragma once
// Sample sequences for distribution ray tracing. A Sampler answers "value of sample i of n in dimension d
// for this pixel" as a pure function, so samples are the same whichever thread or tile asks (DESIGN.md,
// "Numbers"). Dimensions are fixed per meaning (SampleDimension) so that, for instance, the time of a sample
// never correlates with its lens position.
#include <cstdint>
#include <memory>
#include <optional>
#include <string_view>

#include "snell/math/vec3.hpp"

namespace snell::render {

enum SampleDimension : int {
  kPixelX = 0,
  kPixelY = 1,
  kLensU = 2,
  kLensV = 3,
  kTime = 4,
  kSampleDimensions = 5,
};

class Sampler {
 public:
  virtual ~Sampler() = default;
  /// Sample `index` (0 <= index < count) of a pixel's `count` samples in dimension `dim`, in [0,1).
  /// `pixel_seed` scrambles the sequence per pixel (and frame and user seed).
  virtual double get(uint64_t pixel_seed, uint32_t index, uint32_t count, int dim) const = 0;
};

/// "stratified" (jittered strata, shuffled per dimension: a Latin hypercube), "sobol" (Owen-scrambled
/// Sobol), "halton" (Halton with a Cranley-Patterson rotation per pixel); null for other names.
std::unique_ptr<Sampler> make_sampler(std::string_view name);
/// The names make_sampler accepts, for messages.
inline constexpr std::string_view kSamplerNames = "stratified, sobol, halton";

// The sequences themselves, unscrambled, for tests against published values.
/// Sobol point `index` in dimension `dim` (0-based; dimension 0 is van der Corput), Joe & Kuo's direction
/// numbers; dim < kSobolDimensions.
double sobol(uint32_t index, int dim);
inline constexpr int kSobolDimensions = 8;
/// Radical inverse of `index` in the base of the dim-th prime (Halton).
double halton(uint32_t index, int dim);
/// Owen scrambling of a 32-bit fixed-point value: each bit is flipped by a hash of the bits above it.
uint32_t owen_scramble(uint32_t bits, uint64_t seed);

/// The point of the disc of radius 1/2 that (u, v) in the unit square maps to, area-preservingly.
math::Vec2 disc_point(double u, double v);

}  // namespace snell::render
