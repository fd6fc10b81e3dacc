#pragma once
// The scene's objects split by whether their surfaces may let light through, each kind under its own
// accelerator, for the shadow rays of scenes that have both kinds (WhittedIntegrator::shadow_filter).
// There an opaque crossing anywhere between a point and the light makes the light black whatever the
// transparent ones on the way would tint it, so one occlusion query over the opaque objects, which stops
// at the first crossing it finds, settles every shadowed ray; only the rays it lets through walk from
// crossing to crossing, over the transparent objects alone (usually a few: glass, a cloud shell). Without
// the split every shadow ray walked the nearest crossings of the whole scene (benchmark.pov: the opaque
// sockets and text behind its cloud shell).
#include <memory>
#include <string>
#include <vector>

#include "snell/accel/accelerator.hpp"
#include "snell/scene/scene.hpp"

namespace snell::render {

/// Whether no surface of `object` can let light through (its leaves' textures, a CSG's own too).
bool stops_all_light(const scene::Object& object);

class ShadowSplit {
 public:
  /// The split of `scene` under accelerators of `main`'s kind, or null where it would not pay: all
  /// objects of one kind, or a scene so large (over kMaxPrimitives objects and triangles) that a second
  /// structure's memory outweighs the time it saves.
  static std::unique_ptr<ShadowSplit> make(const scene::Scene& scene, const accel::Accelerator& main);

  /// Objects whose every surface stops all light.
  const accel::Accelerator& opaque() const { return *opaque_accel_; }
  /// The others.
  const accel::Accelerator& passing() const { return *passing_accel_; }
  /// For --stats: objects of each kind and the build time.
  std::string summary() const;

  static constexpr size_t kMaxPrimitives = 4'000'000;

 private:
  using Objects = std::vector<std::shared_ptr<const scene::Object>>;
  ShadowSplit(const scene::Scene& scene, const accel::Accelerator& main, Objects opaque, Objects passing);

  scene::Scene opaque_scene_, passing_scene_;
  std::unique_ptr<accel::Accelerator> opaque_accel_, passing_accel_;
  double build_seconds_ = 0;
};

}  // namespace snell::render
