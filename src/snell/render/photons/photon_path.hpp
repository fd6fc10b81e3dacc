#pragma once
// Following one photon from a light through specular reflections and refractions, storing it on every
// surface it reaches after the first bounce (POV-Ray 3.7 photons.cpp, PhotonTrace::ComputeLightedTexture,
// rewritten). The photon splits at each surface into a reflected and a refracted part, each carrying the
// surface's reflectivity or filter colour, until max_trace_level or adc_bailout ends it.
//
// Power: a photon shot through a cone of angular spacing s (radians per unit distance) stands for the light
// colour times s^2 d^2 after a path of length d, so that n photons per area pi r^2 read as the light colour
// itself: POV-Ray's lights do not fall off with distance (photons.cpp, addSurfacePhoton).
#include <vector>

#include "snell/accel/accelerator.hpp"
#include "snell/math/ray.hpp"
#include "snell/render/interior_stack.hpp"
#include "snell/render/photons/photon.hpp"
#include "snell/scene/scene.hpp"

namespace snell::render::photons {

/// The solids a ray is inside after crossing `object`'s surface, and the ratio of indices n1 / n2 there
/// (POV-Ray trace.cpp, ComputeRefraction: a solid nested in another counts from the outer one).
struct Crossing {
  InteriorStack next;
  double eta = 1;
};
Crossing cross_surface(const InteriorStack& inside, const scene::Object* object);

/// Reflectivity of a finish at incidence cosine `cos_i` (POV-Ray trace.cpp, ComputeReflectivity and
/// ComputeMetallic: fresnel or falloff between reflection min and max, tinted by a metallic surface).
math::Color finish_reflectivity(const material::Finish& f, const math::Color& pigment, double cos_i,
                                double relative_ior);

struct PhotonPathLimits {
  int max_trace_level = 5;
  double adc_bailout = 1.0 / 255.0;
};

class PhotonPath {
 public:
  /// `spread`: the angular spacing of the photons being shot (spatial for a parallel light).
  PhotonPath(const accel::Accelerator& accel, const scene::Light& light, const PhotonPathLimits& limits,
             double spread, const scene::PhotonTarget* target);

  /// Follows a photon of colour `power` leaving along `ray` from inside `inside`, appending the photons it
  /// stores to `out`.
  void shoot(const math::Ray& ray, const math::Color& power, const InteriorStack& inside,
             std::vector<Photon>& out);
  /// Whether any photon shot so far hit the target (for autostop).
  bool hit_target() const { return hit_target_; }
  void reset_hit_target() { hit_target_ = false; }

 private:
  struct Leg {
    math::Color power;
    double weight;
    int level;
    /// Length of the path so far.
    double depth;
    /// The last surface let the photon pass unchanged (or it left the light): not stored at the next.
    bool passed;
  };
  void follow(const math::Ray& ray, Leg leg, const InteriorStack& inside, std::vector<Photon>& out);
  /// A hit far along `ray` intersected again from just before it, where rounding is small.
  void refine_far_hit(const math::Ray& ray, scene::SurfaceHit& hit) const;
  void store(const math::Vec3& point, const math::Vec3& incoming, const Leg& leg,
             std::vector<Photon>& out) const;

  const accel::Accelerator& accel_;
  const scene::Light& light_;
  PhotonPathLimits limits_;
  double spread_squared_;
  const scene::PhotonTarget* target_;
  bool hit_target_ = false;
};

}  // namespace snell::render::photons
