#pragma once
// Fractal terrain generators: height samples on regular grids, for height fields and profiles.
// Midpoint displacement and diamond-square follow Paul Martz, "Generating Random Fractal Terrain"
// (gameprogrammer.com/fractal.html): every pass adds a uniform random offset in [-range, range] and then
// multiplies range by 2^-H, so the offsets' variance falls by 2^-2H per level (H = roughness in [0, 1]:
// 1 smooth, 0 rough). The noise terrains sum octaves of Perlin's improved noise (texture/perlin_noise.hpp):
// fBm and Musgrave's ridged multifractal (Ebert et al., Texturing & Modeling, 3rd ed. 2003, ch. 16).
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace snell::procedural {

class TerrainError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

/// `width` x `depth` samples, row-major, row k at z = k / (depth - 1).
struct HeightMap {
  int width = 0;
  int depth = 0;
  std::vector<double> values;
  double& at(int i, int k) {
    return values[static_cast<std::size_t>(k) * static_cast<std::size_t>(width) +
                  static_cast<std::size_t>(i)];
  }
  double at(int i, int k) const {
    return values[static_cast<std::size_t>(k) * static_cast<std::size_t>(width) +
                  static_cast<std::size_t>(i)];
  }
};

/// The largest grid side the generators accept (2^12 + 1).
constexpr int kMaxTerrainSize = 4097;

/// 1D midpoint displacement over `size` = 2^n + 1 samples, both ends 0, first range 1.
std::vector<double> midpoint_profile(int size, double roughness, std::uint64_t seed);

/// Diamond-square on a `size` x `size` grid, size = 2^n + 1; corners 0, first range 1; edge diamonds
/// average their three neighbours. Raw heights (not normalised).
HeightMap diamond_square(int size, double roughness, std::uint64_t seed);

struct NoiseTerrain {
  int size = 257;
  int octaves = 6;
  /// Amplitude falls by lacunarity^-H per octave.
  double roughness = 0.8;
  double lacunarity = 2;
  /// Noise cells across the grid at the first octave.
  double frequency = 4;
  std::uint64_t seed = 0;
  /// Ridged multifractal only: the ridge level and how strongly each octave's ridges weight the next.
  double offset = 1;
  double gain = 2;
};

HeightMap fbm_terrain(const NoiseTerrain& settings);
HeightMap ridged_terrain(const NoiseTerrain& settings);

/// Scales the values linearly onto [0, 1] (all 0 when they are all equal).
void normalize(HeightMap& map);

}  // namespace snell::procedural
