#pragma once
// `density_file df3 "file" [interpolate n]` (POV-Ray 3.7 reference, "Density_File"): a voxel grid read
// from a df3 file laid on the unit cube [0,1)^3, zero outside. The df3 format: three big-endian 16-bit
// sizes (x, y, z), then x-fastest voxels of 1, 2 or 4 big-endian bytes each (the width follows from the
// file's length), scaled so the type's maximum is 1.
#include <filesystem>
#include <memory>
#include <vector>

#include "snell/texture/pattern.hpp"

namespace snell::texture {

struct DensityGrid {
  int nx = 0, ny = 0, nz = 0;
  /// x fastest, then y, then z; each in [0, 1].
  std::vector<float> values;
  float at(int x, int y, int z) const {
    return values[(static_cast<size_t>(z) * ny + y) * static_cast<size_t>(nx) + x];
  }
};

/// Throws std::runtime_error for a file that cannot be read or is not df3 (sizes that do not fit its
/// length, an empty grid).
DensityGrid read_df3(const std::filesystem::path& path);

class DensityFilePattern final : public ValuePattern {
 public:
  /// `interpolation` 0: the voxel the point is in; any other: trilinear between voxel corners, wrapping
  /// around at the far faces as POV-Ray does (its tricubic 2 is approximated by trilinear here).
  DensityFilePattern(std::shared_ptr<const DensityGrid> grid, int interpolation)
      : grid_(std::move(grid)), interpolation_(interpolation) {}
  double value(const Vec3& p) const override;

 private:
  std::shared_ptr<const DensityGrid> grid_;
  int interpolation_;
};

}  // namespace snell::texture
