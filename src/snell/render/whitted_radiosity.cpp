// The Whitted integrator's side of radiosity (render/radiosity/solver.hpp): the pretrace before the
// image and a fresh set of tile records before each tile (its --stats line: WhittedIntegrator::summary).
#include "snell/render/whitted.hpp"

namespace snell::render {

void WhittedIntegrator::prepare(const scene::Camera& camera, int width, int height, const PixelRect& region,
                                double time) {
  if (!radiosity_) return;
  radiosity_->pretrace(width, height, region, [&](double sx, double sy, TraceContext& context) {
    const auto ray = camera.generate_ray(sx, sy, time);
    return ray ? trace_camera_ray(*ray, context) : math::Color(0);
  });
}

void WhittedIntegrator::begin_tile(TraceContext& context) const {
  if (radiosity_) radiosity_->begin_tile(context);
}

}  // namespace snell::render
