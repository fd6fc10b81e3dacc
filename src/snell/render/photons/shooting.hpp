#pragma once
// Shooting caustic photons from every light at every photon target (POV-Ray 3.7
// photonshootingtask.cpp and photons.cpp, LightTargetCombo, rewritten): the photons leave in rings of
// constant angle around the direction to the target's bounding sphere, spaced so that they land `spacing`
// apart at the target's centre, over the solid angle the sphere covers.
//
// Deterministic: each ring has its own random generator seeded by light, target and ring, rings are traced
// in parallel and their photons are joined in ring order, so the map does not depend on the thread count.
#include <cstdint>
#include <vector>

#include "snell/accel/accelerator.hpp"
#include "snell/render/photons/photon.hpp"
#include "snell/scene/scene.hpp"

namespace snell::render::photons {

struct ShootingResult {
  std::vector<Photon> photons;
  /// Photons that left the lights.
  uint64_t shot = 0;
  /// The global spacing used (from `count` when it is given).
  double spacing = 0;
  double seconds = 0;
};

/// Shoots the scene's caustic photons (the scene must have `photons {}` in global_settings).
ShootingResult shoot_caustic_photons(const scene::Scene& scene, const accel::Accelerator& accel);

}  // namespace snell::render::photons
