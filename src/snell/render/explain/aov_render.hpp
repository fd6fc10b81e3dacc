#pragma once
// A render that also keeps, per pixel, what the camera ray met and what the pixel cost (`snell explain
// --aov`, `--heatmap`, `--split-bounces`; issue 14). Samples are placed and seeded exactly as the Renderer
// does (renderer.hpp), so the beauty image equals `snell render`'s.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "snell/accel/accelerator.hpp"
#include "snell/io/image.hpp"
#include "snell/render/renderer.hpp"

namespace snell::render::explain {

/// One named layer: `channels.size()` floats per pixel, row-major, top row first.
struct Layer {
  std::string name;
  std::vector<std::string> channels;
  std::vector<float> values;
  /// Ids (object, material): false colours, not a ramp.
  bool is_id = false;
};

/// The layers `--aov` knows, in this order.
const std::vector<std::string_view>& aov_names();

struct ObjectCost {
  const scene::Object* object;
  /// Its index in scene.objects.
  int index;
  /// Times a ray was tested against it.
  uint64_t tests;
};

struct AovRender {
  io::Image beauty;
  /// The requested layers in the order asked, then the bounce images (sample_observer.hpp).
  std::vector<Layer> layers;
  /// Objects by tests, most first.
  std::vector<ObjectCost> object_costs;
  uint64_t camera_rays = 0;
  uint64_t nodes = 0, primitives = 0, rays = 0;
};

/// Renders with the layers `names` (from aov_names(); throws std::invalid_argument for others) and, with
/// `split_depth` >= 0, the colour split by bounce. Object ids are indices in scene.objects (-1: nothing);
/// material ids number the textures in scene order.
AovRender render_aovs(const scene::Scene& scene, const accel::Accelerator& accelerator,
                      const RenderOptions& options, const std::vector<std::string>& names, int split_depth);

}  // namespace snell::render::explain
