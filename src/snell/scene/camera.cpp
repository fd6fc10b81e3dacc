#include "snell/scene/camera.hpp"

namespace snell::scene {

namespace {

/// POV-Ray's perspective camera: the ray through (sx, sy) goes from `location` towards
/// direction + (sx - 1/2) right + (1/2 - sy) up.
class PerspectiveCamera final : public Camera {
 public:
  explicit PerspectiveCamera(const CameraSpec& s) : spec_(s) {}
  math::Ray generate_ray(double sx, double sy, double time) const override {
    const math::Vec3 d = spec_.direction + (sx - 0.5) * spec_.right + (0.5 - sy) * spec_.up;
    return {spec_.location, normalize(d), time};
  }

 private:
  CameraSpec spec_;
};

/// POV-Ray's orthographic camera: parallel rays along `direction`, the image plane spanned by right and up.
class OrthographicCamera final : public Camera {
 public:
  explicit OrthographicCamera(const CameraSpec& s) : spec_(s) {}
  math::Ray generate_ray(double sx, double sy, double time) const override {
    const math::Vec3 o = spec_.location + (sx - 0.5) * spec_.right + (0.5 - sy) * spec_.up;
    return {o, normalize(spec_.direction), time};
  }

 private:
  CameraSpec spec_;
};

}  // namespace

std::unique_ptr<Camera> make_camera(const CameraSpec& spec) {
  switch (spec.kind) {
    case CameraSpec::Kind::orthographic: return std::make_unique<OrthographicCamera>(spec);
    case CameraSpec::Kind::perspective: break;
  }
  return std::make_unique<PerspectiveCamera>(spec);
}

}  // namespace snell::scene
