#pragma once
// One camera sample of one pixel traced with a RayTreeRecorder watching: the data of `snell explain`.
#include <memory>

#include "snell/accel/accelerator.hpp"
#include "snell/render/explain/ray_tree.hpp"
#include "snell/render/renderer.hpp"

namespace snell::render::explain {

struct PixelExplanation {
  int x = 0, y = 0;
  /// Which sample: 0 the first pass's pixel centre, 1..aa_depth^2 the supersamples (renderer.hpp).
  int sample = 0;
  /// Where the sample lies in the image (0..1).
  math::Vec2 position;
  /// The sample's colour (what the integrator returned).
  math::Color colour{0, 0, 0};
  /// Null where the camera has no ray for the point (outside a fisheye's circle).
  std::unique_ptr<RayNode> tree;
};

/// Traces sample `sample` of pixel (x, y) exactly as the renderer would (same position, same random
/// numbers). Throws std::invalid_argument for a pixel outside the image or a sample out of range (0 without
/// anti-aliasing, else 0..aa_depth^2).
PixelExplanation explain_pixel(const scene::Scene& scene, const accel::Accelerator& accelerator,
                               const RenderOptions& options, int x, int y, int sample);

/// The number of samples a pixel can have: 1, or aa_depth^2 + 1 with anti-aliasing.
int samples_per_pixel(const RenderOptions& options);

}  // namespace snell::render::explain
