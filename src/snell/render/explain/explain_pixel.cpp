#include "snell/render/explain/explain_pixel.hpp"

#include <fmt/core.h>

#include <stdexcept>

#include "snell/render/integrator.hpp"

namespace snell::render::explain {

int samples_per_pixel(const RenderOptions& options) {
  return options.antialias ? options.aa_depth * options.aa_depth + 1 : 1;
}

PixelExplanation explain_pixel(const scene::Scene& scene, const accel::Accelerator& accelerator,
                               const RenderOptions& options, int x, int y, int sample) {
  if (x < 0 || y < 0 || x >= options.width || y >= options.height)
    throw std::invalid_argument(fmt::format("pixel {},{} lies outside the {}x{} image (0..{}, 0..{})", x, y,
                                            options.width, options.height, options.width - 1,
                                            options.height - 1));
  const int samples = samples_per_pixel(options);
  if (sample < 0 || sample >= samples)
    throw std::invalid_argument(fmt::format("sample {} does not exist: a pixel has samples 0..{}{}", sample,
                                            samples - 1, options.antialias ? "" : " without anti-aliasing"));
  const auto integrator = make_integrator(options.integrator, scene, accelerator);
  const auto camera = scene::make_camera(scene.camera);
  PixelExplanation out;
  out.x = x;
  out.y = y;
  out.sample = sample;
  TraceContext context;
  out.position = sample_position(options, x, y, sample);
  seed_camera_sample(context.rng, out.position.u, out.position.v, options);
  const auto ray = camera->generate_ray(out.position.u, out.position.v, options.time);
  if (!ray) return out;
  RayTreeRecorder recorder(scene);
  context.observer = &recorder;
  out.colour = integrator->trace_camera_ray(*ray, context);
  out.tree = recorder.take_root();
  return out;
}

}  // namespace snell::render::explain
