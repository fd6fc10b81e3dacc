#pragma once
// Radiosity as POV-Ray 3.7 defines it (reference "Radiosity"; behaviour of source/core/lighting/
// radiosity.cpp and source/backend/render/radiositytask.cpp): at a diffuse point the ambient term is the
// mean radiance seen along `count` cosine-distributed directions around the normal, times `brightness`,
// recursing up to recursion_limit bounces. The hemisphere is gathered at a sparse set of points and
// interpolated in between (an irradiance cache, Ward et al. 1988): pretrace passes over the image at
// coarse spacing (pretrace_start down to pretrace_end) fill the cache, and the final pass reuses it.
//
// Determinism: the pretrace's tiles are fixed; within a pass a tile sees only the earlier passes' records
// and its own (tile_records.hpp), and at the end of the pass all tiles' records join the cache in tile
// order. The final pass reads the cache and keeps its extra records per tile. So the image is the same
// for any thread count and tile order.
#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "snell/math/color.hpp"
#include "snell/math/vec3.hpp"
#include "snell/memory/budget.hpp"
#include "snell/render/integrator.hpp"
#include "snell/render/radiosity/record_grid.hpp"
#include "snell/render/tiles.hpp"
#include "snell/scene/radiosity_settings.hpp"

namespace snell::render::radiosity {

/// `count` unit directions over the hemisphere around +z, cosine-distributed: a Fibonacci spiral on the
/// unit disc lifted to the hemisphere (Malley's method), so each stands for an equal share of irradiance.
std::vector<math::Vec3> cosine_directions(int count);

/// Unit vectors t, b such that (t, b, n) is a right-handed orthonormal frame; continuous in n except at
/// n.z = -1 (Duff et al. 2017, "Building an Orthonormal Basis, Revisited", JCGT 6(1)).
void orthonormal_frame(const math::Vec3& n, math::Vec3& t, math::Vec3& b);

/// What changes with the bounce depth (POV-Ray's GetRecursionSettings, radiosity.cpp): fewer rays, fewer
/// records needed for reuse, larger error bounds and reuse distances, and the gather rays' trace level
/// and weight.
struct BounceSettings {
  int rays = 35;
  /// Summed weight x 4 that makes a pretrace lookup reuse instead of gathering (nearest_count, 2, 1).
  int reuse_count = 5;
  double error_factor = 1;
  double minimum_reuse = 0.015;
  double maximum_reuse = 0.2;
  int trace_level = 2;
  double ray_weight = 0.5;
  std::vector<math::Vec3> directions;
};

/// The bounce settings for depth `depth` (0 = points seen by the camera) under `settings`.
BounceSettings bounce_settings(const scene::RadiositySettings& settings, int depth);

class Solver {
 public:
  /// `camera` is the camera's location (reuse distances scale with the distance to it); `budget` (may be
  /// null) is charged for the cache; `max_trace_level` caps the gather rays' level.
  Solver(const scene::RadiositySettings& settings, const math::Vec3& camera,
         std::shared_ptr<memory::Budget> budget, int max_trace_level);
  ~Solver();

  /// Whether a point reached through `depth` nested gathers gathers again (depth < recursion_limit).
  bool gathers_at(int depth) const { return depth < settings_.recursion_limit; }
  const scene::RadiositySettings& settings() const { return settings_; }

  /// Colour of a gather ray leaving the point along a unit direction, traced at the given level and
  /// weight; the tracer sets the context's hit_distance.
  using GatherRay = std::function<math::Color(const math::Vec3& direction, int level, double weight)>;

  /// POV-Ray's ambient colour at `point` with unit normal `normal`, for a ray of weight `ray_weight`:
  /// interpolated from the cache, or gathered (and kept in the tile's records) where the cache has too
  /// little; then gray_threshold and brightness.
  math::Color ambient(const math::Vec3& point, const math::Vec3& normal, double ray_weight,
                      TraceContext& context, const GatherRay& trace) const;

  /// Colour of the camera ray through image point (sx, sy) in 0..1, traced with `context`.
  using CameraPoint = std::function<math::Color(double sx, double sy, TraceContext& context)>;
  /// The pretrace passes over `region` of a width x height image; fills the cache. Runs on the calling
  /// task arena's threads.
  void pretrace(int width, int height, const PixelRect& region, const CameraPoint& trace_point);

  /// Starts a final-pass tile: the context keeps its new records apart from other tiles'.
  void begin_tile(TraceContext& context) const;

  /// One line for --stats: passes, records per bounce, memory, gathers.
  std::string summary() const;

 private:
  /// Gathers the hemisphere at a point into `record`; false when the record is not worth keeping (a gather
  /// ray hit something almost at the point).
  bool gather(const math::Vec3& point, const math::Vec3& normal, int depth, TraceContext& context,
              const GatherRay& trace, Record& record) const;
  /// Adds a finished pass's tile records to the cache in tile order, charging the memory budget.
  void merge(std::vector<TileRecords>& tiles);
  TileRecords empty_tile(bool final_pass) const;

  scene::RadiositySettings settings_;
  math::Vec3 camera_;
  std::shared_ptr<memory::Budget> budget_;
  int max_trace_level_;
  std::vector<BounceSettings> bounces_;
  /// The shared cache, one grid per bounce depth; written only between passes.
  std::vector<RecordGrid> cache_;
  uint64_t charged_ = 0;
  bool cache_full_ = false;
  int pretrace_passes_ = 0;
  uint64_t pretrace_rays_ = 0;
  mutable std::atomic<uint64_t> final_gathers_{0};
};

}  // namespace snell::render::radiosity
