#pragma once
#include <vector>

#include "snell/geometry/shape.hpp"

namespace snell::geometry {

/// Samples of a height field: `width` x `depth` heights in [0, 1], row-major, row 0 at z = 0.
struct HeightGrid {
  int width = 0;
  int depth = 0;
  std::vector<float> heights;
  float at(int i, int k) const {
    return heights[static_cast<std::size_t>(k) * static_cast<std::size_t>(width) +
                   static_cast<std::size_t>(i)];
  }
};

/// POV-Ray `height_field` (POV-Ray 3.7 reference, "Height Field"): a grid of samples spread over the unit
/// square x, z in [0, 1], each cell split into two triangles along the same diagonal as POV-Ray
/// (heightfield.cpp); the solid is what lies below the surface. Rays walk the cells with a 2D DDA
/// (Amanatides & Woo 1987) and skip cells, and blocks of cells, whose height range the ray passes above or
/// below.
class HeightField final : public Shape {
 public:
  /// `water_level`: heights below it are raised to it, and cells entirely at it are left out.
  HeightField(HeightGrid grid, bool smooth, double water_level);

  Bounds3 bounds() const override;
  bool intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const override;
  void all_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const override;
  bool inside(const Vec3& p) const override;
  std::string_view kind() const override { return "height_field"; }

  /// The surface height over (x, z) in the unit square.
  double height(double x, double z) const;

 private:
  template <typename Sink>
  void walk(const Ray& ray, double t_min, double t_max, Sink&& sink) const;
  /// Hits in cell (i, k) of the grid-space ray, in increasing t; returns how many (0 to 2).
  int cell_hits(const Ray& grid_ray, int i, int k, double t0, double t1, LocalHit out[2]) const;
  Vec3 vertex_normal(int i, int k) const;
  float h(int i, int k) const { return grid_.at(i, k); }

  HeightGrid grid_;
  bool smooth_;
  double water_;
  /// Per cell: lowest and highest corner height.
  std::vector<float> cell_lo_, cell_hi_;
  /// The same over blocks of kBlock x kBlock cells (the last ones in a row or column smaller): the walk
  /// crosses a block the ray passes above or below in one step instead of cell by cell.
  static constexpr int kBlock = 8;
  int blocks_w_ = 0;
  std::vector<float> block_lo_, block_hi_;
  float y_lo_ = 0, y_hi_ = 0;
};

}  // namespace snell::geometry
