#pragma once
// Caustics for the Whitted integrator: the photon map shot when the integrator is made, the light it adds
// at diffuse surfaces, and the shadow rule that goes with it (POV-Ray 3.7 trace.cpp, ComputeShadowColour:
// a shadow ray through a photon target that refracts the light's photons is fully blocked, since the
// photons bring that light instead of the filtered shadow).
#include <memory>
#include <string>

#include "snell/accel/accelerator.hpp"
#include "snell/render/photons/photon_map.hpp"
#include "snell/render/photons/shooting.hpp"
#include "snell/scene/scene.hpp"

namespace snell::render::photons {

class Caustics {
 public:
  Caustics(ShootingResult shot, const scene::Scene& scene);

  /// Light the caustic photons bring to a surface point (PhotonMap::radiance); nothing at an object with
  /// `collect off`.
  math::Color radiance(const scene::Object& object, const math::Vec3& point, const math::Vec3& raw_normal,
                       const math::Vec3& normal, const PhotonMap::Response& response) const;
  /// Whether a shadow ray from `light` that meets `blocker` is blocked outright (see above).
  bool replaces_shadow(const scene::Light& light, const scene::Object& blocker) const;
  /// One line for --stats: photons shot and stored, memory, spacing, gather radius and time.
  std::string summary() const;
  const PhotonMap& map() const { return map_; }

 private:
  PhotonMap map_;
  uint64_t shot_;
  double spacing_;
  double seconds_;
};

/// The scene's caustics, or null when it has no `photons {}` (or gather maximum 0). Shoots the photons.
std::unique_ptr<Caustics> make_caustics(const scene::Scene& scene, const accel::Accelerator& accel);

}  // namespace snell::render::photons
