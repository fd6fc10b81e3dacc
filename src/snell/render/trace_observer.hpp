#pragma once
// A hook for watching an integrator at work (`snell explain`, AOV layers, light by bounce; issue 14).
// Normal renders leave TraceContext::observer null, so the integrator pays one branch per event. The
// integrator reports a nested stream: ray_begin ... ray_end, with the events of that ray and the rays it
// spawns in between.
#include "snell/math/color.hpp"
#include "snell/math/ray.hpp"
#include "snell/scene/light.hpp"
#include "snell/scene/object.hpp"

namespace snell::render {

/// A part of the colour a ray brings back (POV-Ray 3.7 finish terms plus the two recursive ones).
enum class RayTerm { ambient, emitted, diffuse, phong, specular, reflected, transmitted };

class TraceObserver {
 public:
  virtual ~TraceObserver() = default;
  /// A ray starts. `level` is the recursion level (camera rays 1; shadow rays 0), `weight` its contribution
  /// to the pixel as adc_bailout sees it; `light` is the light a shadow ray looks for.
  virtual void ray_begin(scene::RayKind kind, const math::Ray& ray, int level, double weight,
                         const scene::Light* light) = 0;
  /// The nearest hit of the current ray, or null for a miss.
  virtual void ray_hit(const scene::SurfaceHit* hit) = 0;
  /// A shadow ray meets an object: opaque ones block it, transparent ones tint it and it goes on.
  virtual void shadow_blocker(const scene::SurfaceHit& hit, bool opaque) = 0;
  /// A term adds `value` to the current ray's colour: `weight` times the light or child colour it scales.
  virtual void term(RayTerm term, const math::Color& weight, const math::Color& value) = 0;
  /// The refracted ray was not sent: total internal reflection (the reflected one follows instead).
  virtual void total_internal_reflection() = 0;
  /// The current ray ends with `result` (for a shadow ray, the light that got through).
  virtual void ray_end(const math::Color& result) = 0;
};

/// Reports one ray to an observer for a scope: ray_begin now, ray_end with the last result() on leaving.
class ObservedRay {
 public:
  ObservedRay(TraceObserver* observer, scene::RayKind kind, const math::Ray& ray, int level, double weight,
              const scene::Light* light = nullptr)
      : observer_(observer) {
    if (observer_) observer_->ray_begin(kind, ray, level, weight, light);
  }
  ~ObservedRay() {
    if (observer_) observer_->ray_end(result_);
  }
  ObservedRay(const ObservedRay&) = delete;
  ObservedRay& operator=(const ObservedRay&) = delete;

  void hit(const scene::SurfaceHit* hit) const {
    if (observer_) observer_->ray_hit(hit);
  }
  /// Keeps `c` as the ray's result and returns it.
  math::Color result(const math::Color& c) {
    result_ = c;
    return c;
  }

 private:
  TraceObserver* observer_;
  math::Color result_{0, 0, 0};
};

}  // namespace snell::render
