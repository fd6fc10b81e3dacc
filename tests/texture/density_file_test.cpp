// density_file (texture/density_file.hpp) on hand-made df3 files: the format's big-endian header and
// voxels (POV-Ray 3.7 reference, "Density_File"), the voxel lookup and the trilinear blend.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "snell/texture/density_file.hpp"

using namespace snell::texture;
using snell::math::Vec3;

namespace {

/// Writes a df3 file of nx x ny x nz voxels of `width` bytes, values as given (x fastest).
std::filesystem::path write_df3(const std::string& name, int nx, int ny, int nz, int width,
                                const std::vector<unsigned long long>& voxels) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("snell_df3_" + name + "_" + std::to_string(getpid()) + ".df3");
  std::ofstream out(path, std::ios::binary);
  auto put = [&](unsigned long long v, int bytes) {
    for (int i = bytes - 1; i >= 0; --i) out.put(static_cast<char>((v >> (8 * i)) & 0xff));
  };
  put(static_cast<unsigned>(nx), 2), put(static_cast<unsigned>(ny), 2), put(static_cast<unsigned>(nz), 2);
  for (unsigned long long v : voxels) put(v, width);
  return path;
}

}  // namespace

TEST(DensityFile, ReadsEachVoxelWidthBigEndian) {
  const auto p8 = write_df3("w8", 2, 1, 1, 1, {0, 255});
  const auto p16 = write_df3("w16", 2, 1, 1, 2, {0x8000, 65535});
  const auto p32 = write_df3("w32", 1, 1, 2, 4, {0xffffffffull, 0x40000000ull});
  const DensityGrid g8 = read_df3(p8), g16 = read_df3(p16), g32 = read_df3(p32);
  EXPECT_EQ(g8.nx, 2);
  EXPECT_FLOAT_EQ(g8.at(1, 0, 0), 1.0f);
  EXPECT_FLOAT_EQ(g16.at(0, 0, 0), static_cast<float>(32768.0 / 65535.0));
  EXPECT_EQ(g32.nz, 2);
  EXPECT_FLOAT_EQ(g32.at(0, 0, 0), 1.0f);
  EXPECT_NEAR(g32.at(0, 0, 1), 0.25, 1e-9);
  for (const auto& p : {p8, p16, p32}) std::filesystem::remove(p);
}

TEST(DensityFile, NearestVoxelTrilinearBlendAndZeroOutside) {
  // 2 x 1 x 1: voxel x=0 is 0, x=1 is 1 (8-bit).
  const auto path = write_df3("lookup", 2, 1, 1, 1, {0, 255});
  const auto grid = std::make_shared<const DensityGrid>(read_df3(path));
  std::filesystem::remove(path);
  const DensityFilePattern nearest(grid, 0), trilinear(grid, 1);
  EXPECT_DOUBLE_EQ(nearest.value({0.3, 0.5, 0.5}), 0.0);
  EXPECT_DOUBLE_EQ(nearest.value({0.7, 0.5, 0.5}), 1.0);
  // Trilinear from voxel corners: x = 0.25 is a quarter of the way from voxel 0 to voxel 1 (grid x 0.5).
  EXPECT_NEAR(trilinear.value({0.25, 0.5, 0.5}), 0.5, 1e-12);
  EXPECT_NEAR(trilinear.value({0.1, 0.5, 0.5}), 0.2, 1e-12);
  // Past the last voxel the blend wraps to the first, as POV-Ray's does: x = 0.75 is halfway 1 -> 0.
  EXPECT_NEAR(trilinear.value({0.75, 0.5, 0.5}), 0.5, 1e-12);
  for (const Vec3& outside : {Vec3{-0.1, 0.5, 0.5}, Vec3{0.5, 1.0, 0.5}, Vec3{0.5, 0.5, 2}})
    EXPECT_EQ(nearest.value(outside), 0.0);
}

TEST(DensityFile, RejectsFilesThatAreNotDf3) {
  const auto short_file = write_df3("short", 3, 3, 3, 1, {1, 2, 3});
  EXPECT_THROW(read_df3(short_file), std::runtime_error);
  std::filesystem::remove(short_file);
  const auto empty = write_df3("empty", 0, 4, 4, 1, {});
  EXPECT_THROW(read_df3(empty), std::runtime_error);
  std::filesystem::remove(empty);
  EXPECT_THROW(read_df3("/nonexistent/snell.df3"), std::runtime_error);
}
