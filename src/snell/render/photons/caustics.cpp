#include "snell/render/photons/caustics.hpp"

#include <fmt/format.h>

#include "snell/memory/budget.hpp"

namespace snell::render::photons {

Caustics::Caustics(ShootingResult shot, const scene::Scene& scene)
    : map_(std::move(shot.photons), *scene.settings.photons, scene.memory_budget),
      shot_(shot.shot),
      spacing_(shot.spacing),
      seconds_(shot.seconds) {}

math::Color Caustics::radiance(const scene::Object& object, const math::Vec3& point,
                               const math::Vec3& raw_normal, const math::Vec3& normal,
                               const PhotonMap::Response& response) const {
  if (!object.flags.photons.collect) return math::Color(0);
  return map_.radiance(point, raw_normal, normal, object.flags.double_illuminate, response);
}

bool Caustics::replaces_shadow(const scene::Light& light, const scene::Object& blocker) const {
  if (map_.size() == 0) return false;
  const scene::ObjectPhotons& p = blocker.flags.photons;
  return p.target && p.refraction != scene::PhotonSwitch::off &&
         light.photons.refraction != scene::PhotonSwitch::off &&
         (p.refraction == scene::PhotonSwitch::on || light.photons.refraction == scene::PhotonSwitch::on);
}

std::string Caustics::summary() const {
  return fmt::format(
      "photons: {} shot, {} stored ({}), spacing {:.4g}, gather radius {:.4g}, shot in {:.3f}s", shot_,
      map_.size(), memory::format_size(map_.memory_bytes()), spacing_, map_.gather_radius(), seconds_);
}

std::unique_ptr<Caustics> make_caustics(const scene::Scene& scene, const accel::Accelerator& accel) {
  if (!scene.settings.photons || scene.settings.photons->gather_max <= 0) return nullptr;
  return std::make_unique<Caustics>(shoot_caustic_photons(scene, accel), scene);
}

}  // namespace snell::render::photons
