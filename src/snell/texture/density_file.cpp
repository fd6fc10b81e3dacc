#include "snell/texture/density_file.hpp"

#include <cmath>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace snell::texture {

DensityGrid read_df3(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open the file");
  const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)),
                                         std::istreambuf_iterator<char>());
  if (bytes.size() < 6) throw std::runtime_error("too short for a df3 header");
  auto big_endian = [&](size_t at, int width) {
    unsigned long long v = 0;
    for (int i = 0; i < width; ++i) v = (v << 8) | bytes[at + static_cast<size_t>(i)];
    return v;
  };
  DensityGrid grid;
  grid.nx = static_cast<int>(big_endian(0, 2));
  grid.ny = static_cast<int>(big_endian(2, 2));
  grid.nz = static_cast<int>(big_endian(4, 2));
  const size_t count = static_cast<size_t>(grid.nx) * grid.ny * grid.nz;
  if (count == 0) throw std::runtime_error("the df3 grid is empty");
  const size_t data = bytes.size() - 6;
  const int width = static_cast<int>(data / count);
  if (data % count != 0 || (width != 1 && width != 2 && width != 4))
    throw std::runtime_error("its length does not fit a " + std::to_string(grid.nx) + "x" +
                             std::to_string(grid.ny) + "x" + std::to_string(grid.nz) +
                             " df3 grid of 1, 2 or 4 byte voxels");
  const double max = width == 1 ? 255.0 : width == 2 ? 65535.0 : 4294967295.0;
  grid.values.resize(count);
  for (size_t i = 0; i < count; ++i)
    grid.values[i] = static_cast<float>(static_cast<double>(big_endian(6 + i * width, width)) / max);
  return grid;
}

double DensityFilePattern::value(const Vec3& p) const {
  if (!(p.x >= 0 && p.x < 1 && p.y >= 0 && p.y < 1 && p.z >= 0 && p.z < 1)) return 0;
  const DensityGrid& g = *grid_;
  const double gx = p.x * g.nx, gy = p.y * g.ny, gz = p.z * g.nz;
  const int x0 = std::min(static_cast<int>(gx), g.nx - 1), y0 = std::min(static_cast<int>(gy), g.ny - 1),
            z0 = std::min(static_cast<int>(gz), g.nz - 1);
  if (interpolation_ == 0) return g.at(x0, y0, z0);
  // Trilinear from the voxel's corner towards the next voxel, the last wrapping to the first (as POV-Ray's
  // pattern.cpp density_file does).
  const int x1 = (x0 + 1) % g.nx, y1 = (y0 + 1) % g.ny, z1 = (z0 + 1) % g.nz;
  const double tx = gx - x0, ty = gy - y0, tz = gz - z0;
  auto lerp = [](double a, double b, double t) { return a + (b - a) * t; };
  auto plane = [&](int z) {
    return lerp(lerp(g.at(x0, y0, z), g.at(x1, y0, z), tx), lerp(g.at(x0, y1, z), g.at(x1, y1, z), tx), ty);
  };
  return lerp(plane(z0), plane(z1), tz);
}

}  // namespace snell::texture
