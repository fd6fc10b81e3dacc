#pragma once
// Reproducible pseudo-random numbers attached to integer lattice cells, for the cellular patterns
// (cells, crackle): the same cell always gets the same numbers, independent of threads and of the order
// cells are visited. The mixer is the "lowbias32" integer hash (Chris Wellons, "Prospecting for Hash
// Functions", 2018), which spreads a one-bit change of the input over all output bits.
#include <cstdint>

#include "snell/math/vec3.hpp"

namespace snell::texture {

constexpr uint32_t mix_bits(uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}

/// A hash of cell (x, y, z) and a `stream` number selecting independent values for the same cell.
constexpr uint32_t lattice_hash(int x, int y, int z, uint32_t stream = 0) {
  uint32_t h = mix_bits(static_cast<uint32_t>(z) + 0x9e3779b9U * (stream + 1));
  h = mix_bits(static_cast<uint32_t>(y) ^ h);
  return mix_bits(static_cast<uint32_t>(x) ^ h);
}

/// A number in [0, 1) for the cell.
constexpr double lattice_random(int x, int y, int z, uint32_t stream = 0) {
  return lattice_hash(x, y, z, stream) * (1.0 / 4294967296.0);
}

/// A point uniformly placed inside the unit cube of cell (x, y, z).
inline math::Vec3 point_in_cell(int x, int y, int z) {
  return {x + lattice_random(x, y, z, 0), y + lattice_random(x, y, z, 1), z + lattice_random(x, y, z, 2)};
}

}  // namespace snell::texture
