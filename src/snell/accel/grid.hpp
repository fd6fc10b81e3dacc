#pragma once
// Uniform grid walked with the 3D-DDA of Amanatides and Woo ("A fast voxel traversal algorithm for ray
// tracing", Eurographics 1987). About the cube root of twice the object count cells along the longest
// axis. An object listed in several cells is tested once per ray (Mailbox).
#include <array>
#include <cstdint>
#include <vector>

#include "snell/accel/accelerator.hpp"
#include "snell/accel/nearest_hit.hpp"

namespace snell::accel {

class Grid final : public Accelerator {
 public:
  explicit Grid(const scene::Scene& scene);
  bool intersect(const math::Ray& ray, double t_min, double t_max, scene::RayKind kind,
                 scene::SurfaceHit& hit) const override;
  std::string_view name() const override { return "grid"; }
  AcceleratorStats stats() const override { return stats_; }

 private:
  size_t cell_index(const std::array<int, 3>& c) const {
    return (static_cast<size_t>(c[2]) * resolution_[1] + c[1]) * resolution_[0] + c[0];
  }

  math::Bounds3 box_;
  std::array<int, 3> resolution_{};
  math::Vec3 cell_size_;
  /// Objects of cell i: cell_objects_[cell_start_[i] .. cell_start_[i + 1]), indices into objects_.
  std::vector<uint32_t> cell_start_;
  std::vector<uint32_t> cell_objects_;
  std::vector<const scene::Object*> objects_;
  /// plain_triangle of each of objects_.
  std::vector<PlainTriangle> triangles_;
  /// Objects too large to list cell by cell (they would cover a quarter of the grid), and unbounded ones.
  std::vector<const scene::Object*> everywhere_;
  AcceleratorStats stats_;
};

}  // namespace snell::accel
