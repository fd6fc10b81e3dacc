#include "snell/render/shadow_split.hpp"

#include <chrono>

#include <fmt/format.h>

#include "snell/scene/csg.hpp"

namespace snell::render {

bool stops_all_light(const scene::Object& object) {
  if (object.texture && object.texture->may_transmit()) return false;
  if (object.csg)
    for (const auto& child : object.csg->children())
      if (!stops_all_light(*child)) return false;
  return true;
}

std::unique_ptr<ShadowSplit> ShadowSplit::make(const scene::Scene& scene, const accel::Accelerator& main) {
  const accel::AcceleratorStats stats = main.stats();
  if (stats.objects + stats.native_triangles > kMaxPrimitives) return nullptr;
  Objects opaque, passing;
  for (const auto& o : scene.objects) (stops_all_light(*o) ? opaque : passing).push_back(o);
  if (opaque.empty() || passing.empty()) return nullptr;
  return std::unique_ptr<ShadowSplit>(new ShadowSplit(scene, main, std::move(opaque), std::move(passing)));
}

ShadowSplit::ShadowSplit(const scene::Scene& scene, const accel::Accelerator& main, Objects opaque,
                         Objects passing)
    : opaque_scene_(scene), passing_scene_(scene) {
  const auto start = std::chrono::steady_clock::now();
  opaque_scene_.objects = std::move(opaque);
  passing_scene_.objects = std::move(passing);
  opaque_accel_ = accel::make_accelerator(main.name(), opaque_scene_);
  passing_accel_ = accel::make_accelerator(main.name(), passing_scene_);
  build_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string ShadowSplit::summary() const {
  return fmt::format("shadow split: {} opaque, {} transparent objects (built in {:.3f}s)",
                     opaque_scene_.objects.size(), passing_scene_.objects.size(), build_seconds_);
}

}  // namespace snell::render
