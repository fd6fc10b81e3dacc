#pragma once
#include <memory>

#include "snell/math/ray.hpp"
#include "snell/math/vec3.hpp"

namespace snell::scene {

/// A POV-Ray camera after all of its modifiers are applied (the parser resolves look_at, sky, angle and
/// transforms into these final vectors). Left-handed like POV-Ray: right x up = direction.
struct CameraSpec {
  enum class Kind { perspective, orthographic };
  Kind kind = Kind::perspective;
  math::Vec3 location{0, 0, 0};
  math::Vec3 direction{0, 0, 1};
  math::Vec3 up{0, 1, 0};
  math::Vec3 right{1.33, 0, 0};
  // focal blur (distribution issue)
  double aperture = 0;
  int blur_samples = 0;
  math::Vec3 focal_point{0, 0, 1};
};

/// Makes primary rays. (sx, sy) are image-plane coordinates in [0,1]^2 with y growing downward
/// (pixel centre of column i is (i + 0.5) / width).
class Camera {
 public:
  virtual ~Camera() = default;
  virtual math::Ray generate_ray(double sx, double sy, double time) const = 0;
};

std::unique_ptr<Camera> make_camera(const CameraSpec& spec);

}  // namespace snell::scene
