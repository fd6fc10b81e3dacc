#pragma once
// An Integrator turns a camera ray into a colour. Implementations: `whitted` (POV-Ray 3.7 compatible);
// `path` comes later. They read the immutable scene and accelerator; all mutable state is in TraceContext.
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "snell/accel/accelerator.hpp"
#include "snell/math/color.hpp"
#include "snell/math/constants.hpp"
#include "snell/math/pcg32.hpp"
#include "snell/math/ray.hpp"
#include "snell/render/lit_lights.hpp"
#include "snell/render/radiosity/tile_records.hpp"
#include "snell/render/ray_counters.hpp"
#include "snell/render/tiles.hpp"
#include "snell/render/trace_observer.hpp"
#include "snell/scene/scene.hpp"

namespace snell::render {

/// Per-thread scratch for tracing: the sample's random numbers and the ray counters.
struct TraceContext {
  math::Pcg32 rng;
  /// The camera ray's shutter time: every ray it spawns (shadow, reflected, refracted) sees the scene then.
  double time = 0;
  RayCounters counters;
  /// Pixels this thread supersampled (summed after the render: a shared counter bounced between cores).
  uint64_t supersampled_pixels = 0;
  /// Null in normal renders; set by `snell explain` and the AOV layers to watch the rays
  /// (trace_observer.hpp).
  TraceObserver* observer = nullptr;
  /// How many radiosity gathers the current ray is nested in (POV-Ray's radiosityRecursionDepth).
  int radiosity_depth = 0;
  /// Distance to the surface the last traced ray hit (infinite when it hit none): radiosity's reuse radius.
  double hit_distance = math::kInfinity;
  /// Radiosity records this tile gathered (render/radiosity/solver.hpp).
  radiosity::TileRecords radiosity_tile;
  /// Per light (by its index in Scene::lights): the object that last stopped one of its shadow rays, tried
  /// first by the next one (POV-Ray's shadow cache, lighting.cpp). Neighbouring points usually share it.
  struct ShadowBlocker {
    const scene::Object* object = nullptr;
    /// No surface of it lets light through: a crossing is enough, no hit need be built.
    bool stops_all_light = false;
  };
  std::vector<ShadowBlocker> shadow_blockers;
  /// Shadow-tested light colours of the surface points being shaded, one frame of Scene::lights.size()
  /// entries per nesting level (render/lit_lights.hpp); reused by every layer and map entry of a texture.
  LitLights lit_lights;
};

class Integrator {
 public:
  virtual ~Integrator() = default;
  /// Radiance arriving along a camera ray (unit direction) from surfaces nearer than `max_distance` (a
  /// mesh camera's limit; POV-Ray's TraceRay maxDepth).
  virtual math::Color trace_camera_ray(const math::Ray& ray, TraceContext& context,
                                       double max_distance = math::kInfinity) const = 0;
  virtual std::string_view name() const = 0;
  /// Work before the image's tiles (radiosity's pretrace), on the render's threads.
  virtual void prepare(const scene::Camera& /*camera*/, int /*width*/, int /*height*/,
                       const PixelRect& /*region*/, double /*time*/) {}
  /// Called before each tile with the context that will render it.
  virtual void begin_tile(TraceContext& /*context*/) const {}
  /// True when a sample's colour depends on the tile that traces it (radiosity's per-tile records), so
  /// that a tile must trace every sample it uses itself.
  virtual bool samples_depend_on_tile() const { return false; }
  /// A line for --stats about the integrator's own work (empty: nothing to say).
  virtual std::string summary() const { return {}; }
};

/// `name` is "whitted". Throws std::invalid_argument for unknown names. Scene and accelerator must outlive
/// it.
std::unique_ptr<Integrator> make_integrator(std::string_view name, const scene::Scene& scene,
                                            const accel::Accelerator& accelerator);

}  // namespace snell::render
