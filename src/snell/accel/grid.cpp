#include "snell/accel/grid.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "snell/accel/indexed_objects.hpp"
#include "snell/accel/mailbox.hpp"
#include "snell/accel/nearest_hit.hpp"
#include "snell/geometry/ray_box.hpp"

namespace snell::accel {

namespace {

constexpr double kCellsPerObject = 2.0;
constexpr int kMaxResolution = 128;

}  // namespace

Grid::Grid(const scene::Scene& scene) {
  const auto start = std::chrono::steady_clock::now();
  const IndexedObjects indexed(scene);
  everywhere_ = indexed.unbounded;
  objects_ = indexed.bounded;
  triangles_ = plain_triangles(objects_);
  box_ = indexed.scene_box;
  const size_t n = objects_.size();
  if (n > 0) {
    const math::Vec3 extent = box_.extent();
    const double side = max_component(extent) / std::cbrt(kCellsPerObject * static_cast<double>(n));
    for (int a = 0; a < 3; ++a) {
      const double cells = side > 0 ? std::ceil(extent[a] / side) : 1;
      resolution_[a] = static_cast<int>(std::clamp(cells, 1.0, static_cast<double>(kMaxResolution)));
      // A flat axis gets one cell of the scene's size, so no cell size is zero.
      cell_size_[a] = extent[a] > 0 ? extent[a] / resolution_[a] : std::max(side, 1.0);
    }
    const size_t cells = static_cast<size_t>(resolution_[0]) * resolution_[1] * resolution_[2];
    const size_t too_large = std::max<size_t>(8, cells / 4);

    // Two passes (count, then fill) build the cell lists in place.
    std::vector<std::array<int, 6>> ranges(n);
    std::vector<bool> listed(n, false);
    cell_start_.assign(cells + 1, 0);
    for (size_t i = 0; i < n; ++i) {
      const math::Bounds3& b = indexed.boxes[i];
      size_t covered = 1;
      for (int a = 0; a < 3; ++a) {
        const auto cell_of = [&](double x) {
          return std::clamp(static_cast<int>(std::floor((x - box_.lo[a]) / cell_size_[a])), 0,
                            resolution_[a] - 1);
        };
        // A billionth of a cell of margin: an object touching a cell plane is listed on both sides, so
        // the rounding of the walk's plane crossings can never skip it.
        const double margin = 1e-9 * cell_size_[a];
        ranges[i][a] = cell_of(b.lo[a] - margin);
        ranges[i][a + 3] = cell_of(b.hi[a] + margin);
        covered *= static_cast<size_t>(ranges[i][a + 3] - ranges[i][a] + 1);
      }
      listed[i] = covered <= too_large;
      if (!listed[i]) everywhere_.push_back(objects_[i]);
    }
    const auto for_each_cell = [&](size_t i, auto&& visit) {
      const auto& r = ranges[i];
      for (int z = r[2]; z <= r[5]; ++z)
        for (int y = r[1]; y <= r[4]; ++y)
          for (int x = r[0]; x <= r[3]; ++x) visit(cell_index({x, y, z}));
    };
    for (size_t i = 0; i < n; ++i)
      if (listed[i]) for_each_cell(i, [&](size_t c) { ++cell_start_[c + 1]; });
    for (size_t c = 0; c < cells; ++c) cell_start_[c + 1] += cell_start_[c];
    cell_objects_.resize(cell_start_[cells]);
    std::vector<uint32_t> fill(cell_start_.begin(), cell_start_.end() - 1);
    for (size_t i = 0; i < n; ++i)
      if (listed[i]) for_each_cell(i, [&](size_t c) { cell_objects_[fill[c]++] = static_cast<uint32_t>(i); });
  }
  stats_ = structure_stats(scene.objects.size(), indexed.unbounded.size(),
                           cell_start_.empty() ? 0 : cell_start_.size() - 1,
                           (cell_start_.size() + cell_objects_.size()) * sizeof(uint32_t) +
                               objects_.size() * (sizeof(objects_[0]) + sizeof(PlainTriangle)),
                           start);
}

bool Grid::intersect(const math::Ray& ray, double t_min, double t_max, scene::RayKind kind,
                     scene::SurfaceHit& hit) const {
  NearestHit nearest(ray, t_min, t_max, kind, hit);
  for (const scene::Object* o : everywhere_) nearest.test_general(*o);
  if (cell_start_.empty() || !(t_min < t_max)) return nearest.finish();
  const geometry::RayBox slabs(ray);
  double entry, exit;
  if (!slabs.enter(box_, t_min, nearest.t_max(), entry, exit)) return nearest.finish();

  // Start cell: the entry point nudged a millionth of a cell back along the ray, so rounding can only
  // start the walk one cell early (harmless), never one cell late.
  const math::Vec3 p = ray.at(entry);
  std::array<int, 3> cell{}, step{};
  math::Vec3 inverse;
  for (int a = 0; a < 3; ++a) {
    const double d = ray.direction[a];
    step[a] = d > 0 ? 1 : (d < 0 ? -1 : 0);
    inverse[a] = 1.0 / d;
    const double coordinate = (p[a] - box_.lo[a]) / cell_size_[a] - 1e-6 * step[a];
    // NaN (NaN rays) and out-of-range values clamp into the grid; the walk still ends at the boundary.
    cell[a] = std::isnan(coordinate)
                  ? 0
                  : static_cast<int>(std::clamp(std::floor(coordinate), 0.0, resolution_[a] - 1.0));
  }
  // t where the ray leaves the current cell through its far plane on axis a (infinite when parallel).
  const auto plane_t = [&](int a) {
    if (step[a] == 0) return math::kInfinity;
    const int plane = step[a] > 0 ? cell[a] + 1 : cell[a];
    return (box_.lo[a] + plane * cell_size_[a] - ray.origin[a]) * inverse[a];
  };
  math::Vec3 next{plane_t(0), plane_t(1), plane_t(2)};

  Mailbox mailbox;
  NodeTally tally;
  for (;;) {
    const size_t c = cell_index(cell);
    tally.visit();
    for (uint32_t k = cell_start_[c]; k < cell_start_[c + 1]; ++k) {
      const uint32_t i = cell_objects_[k];
      if (mailbox.first_visit(i)) nearest.test(*objects_[i], triangles_[i]);
    }
    // Every object not yet tested lies in cells beyond this one, so a hit (or window end) before the
    // cell's exit is final.
    const int axis = next.x < next.y ? (next.x < next.z ? 0 : 2) : (next.y < next.z ? 1 : 2);
    const double cell_exit = next[axis];
    if (!(cell_exit < nearest.t_max()) || step[axis] == 0) break;
    cell[axis] += step[axis];
    if (cell[axis] < 0 || cell[axis] >= resolution_[axis]) break;
    next[axis] = plane_t(axis);
  }
  return nearest.finish();
}

}  // namespace snell::accel
