#pragma once
// POV-Ray 3.7's own noise functions, so that noise patterns give the same pixels as POV-Ray renders
// (POV-Ray 3.7 reference, "noise_generator"; algorithm from POV-Ray's source, core/material/noise.cpp and
// portablenoise.cpp, reimplemented here):
//   1 "original": lattice noise summing, at the 8 cell corners, a hashed linear function weighted by the
//     cubic S-curve, shifted by 0.5 and clamped to [0, 1];
//   2 "range corrected" (3.7's default): the same sum stretched to fill [0, 1];
//   3 "Perlin": Perlin's 1985 gradient noise, scaled to about [0, 1].
#include <cstddef>
#include <memory>

#include "snell/math/vec3.hpp"

namespace snell::texture {

enum class NoiseGenerator { original = 1, range_corrected = 2, perlin = 3 };

/// POV-Ray's generator when a scene names none (3.7: range corrected).
constexpr NoiseGenerator kDefaultNoiseGenerator = NoiseGenerator::range_corrected;

/// The generator a pattern uses: its own `noise_generator N`, or a cell shared with the parser that holds
/// the scene's `global_settings { noise_generator N }`, which may come after the pattern (POV-Ray too
/// resolves a pattern's default generator from the scene only when rendering). Empty: 3.7's default.
class NoiseChoice {
 public:
  NoiseChoice() = default;
  explicit NoiseChoice(std::shared_ptr<const NoiseGenerator> cell) : cell_(std::move(cell)) {}
  NoiseGenerator get() const { return cell_ ? *cell_ : kDefaultNoiseGenerator; }

 private:
  std::shared_ptr<const NoiseGenerator> cell_;
};

/// POV-Ray's Hash3d of a lattice cell: its noise's shuffled table applied to each coordinate's low 12 bits in
/// turn, a number in [0, 4096).
int povray_hash3d(int x, int y, int z);

/// POV-Ray 3.7's PatternRands(i): entry i (modulo 32768) of a table of 32768 numbers in [0, 1), the first
/// draws of a Mersenne twister (mt19937, default seed) each divided by 2^32 (randomsequences.cpp).
double povray_pattern_random(size_t index);

/// The random point POV-Ray's crackle and facets place in the unit cube of cell (x, y, z) (pattern.cpp,
/// IntPickInCube): the cell's corner plus three table numbers drawn at its hash.
math::Vec3 povray_point_in_cube(int x, int y, int z);

/// POV-Ray's Jitter2d(x, y) (jitter.h): the offsets, each in [-0.5, 0.5], by which its anti-aliasing moves
/// the supersample at image point (x, y) (pixel units), read through the noise's hash table from a table of
/// 256 offsets (a binary digital sequence: entry i is the XOR of one 16-bit generator per set bit of i).
math::Vec2 povray_jitter2d(double x, double y);

/// POV-Ray's Noise(): a scalar in [0, 1].
double povray_noise(const math::Vec3& p, NoiseGenerator generator = kDefaultNoiseGenerator);

/// How many points povray_noise_lanes takes at once (the register code's lane count).
inline constexpr int kNoiseLanes = 8;

/// povray_noise at kNoiseLanes points (x[l], y[l], z[l]) at once, bit for bit the same values: the
/// lattice arithmetic runs on whole vectors of points, the table look-ups point by point.
void povray_noise_lanes(const double* x, const double* y, const double* z, double* out,
                        NoiseGenerator generator = kDefaultNoiseGenerator);

/// povray_noise at the points p * scales[i] for i < count, into out[i] (the octaves of a fractal sum),
/// computed kNoiseLanes points at a time; the same values as one call per point.
void povray_noise_scaled(const math::Vec3& p, const double* scales, int count, double* out,
                         NoiseGenerator generator = kDefaultNoiseGenerator);

/// povray_dnoise at the points p * scales[i] for i < count, into out[i], kNoiseLanes points at a time;
/// the same values as one call per point.
void povray_dnoise_scaled(const math::Vec3& p, const double* scales, int count, math::Vec3* out);

/// POV-Ray's DNoise(): a vector whose components lie in about [-1, 1] (same for every generator).
math::Vec3 povray_dnoise(const math::Vec3& p);

/// POV-Ray's Turbulence(): noise summed over `octaves`, each `lambda` times the frequency and `omega`
/// times the weight of the previous one. Generators 2 and 3 use each octave as 2 * noise - 0.5.
double povray_turbulence(const math::Vec3& p, int octaves, double lambda, double omega,
                         NoiseGenerator generator = kDefaultNoiseGenerator);

/// POV-Ray's DTurbulence(): the same octave sum of povray_dnoise.
math::Vec3 povray_vector_turbulence(const math::Vec3& p, int octaves, double lambda, double omega);

}  // namespace snell::texture
