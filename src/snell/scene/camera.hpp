#pragma once
#include <memory>
#include <optional>

#include "snell/math/ray.hpp"
#include "snell/math/vec3.hpp"

namespace snell::scene {

struct MeshCameraSpec;  // mesh_camera.hpp

/// A POV-Ray camera after all of its modifiers are applied (the parser resolves look_at, sky, angle and
/// transforms into these final vectors). Left-handed like POV-Ray: right x up = direction.
struct CameraSpec {
  enum class Kind {
    perspective,
    orthographic,
    fisheye,
    ultra_wide_angle,
    omnimax,
    panoramic,
    cylinder1,  // vertical cylinder, fixed viewpoint
    cylinder2,  // horizontal cylinder, fixed viewpoint
    cylinder3,  // vertical cylinder, viewpoint moves along up
    cylinder4,  // horizontal cylinder, viewpoint moves along right
    spherical,
    mesh,  // mesh_camera: rays from the faces of meshes (mesh_camera.hpp)
  };
  Kind kind = Kind::perspective;
  math::Vec3 location{0, 0, 0};
  math::Vec3 direction{0, 0, 1};
  math::Vec3 up{0, 1, 0};
  math::Vec3 right{1.33, 0, 0};
  /// Field of view in degrees for fisheye, ultra_wide_angle, omnimax, panoramic and cylinder cameras
  /// (perspective and orthographic fold `angle` into `direction` instead). POV-Ray's default is 90.
  double angle = 90;
  /// Spherical camera: horizontal and vertical field of view in degrees.
  double h_angle = 360;
  double v_angle = 180;
  // Focal blur (POV-Ray reference "Focal Blur"). On when aperture != 0 and blur_samples > 0; a pixel takes
  // at most blur_samples rays and stops once confidence/variance say its mean colour is good enough.
  double aperture = 0;
  int blur_samples = 0;
  int blur_samples_min = 0;  // no early stop before this many (`blur_samples MIN, MAX`)
  double confidence = 0.9;
  double variance = 1.0 / 10000.0;
  math::Vec3 focal_point{0, 0, 1};
  /// Distance from location to the plane in focus, measured along `direction` (POV-Ray: |focal_point -
  /// location| when focal_point is given, else the length of `direction`). Negative: not set yet (the
  /// parser resolves it; a camera built without one focuses at the length of `direction`).
  double focal_distance = -1;

  // Motion blur (a snell extension, docs/language.md "Motion blur"): rays get times spread over
  // [shutter_open, shutter_close]; each pixel takes shutter_samples of them (or --spp samples).
  double shutter_open = 0;
  double shutter_close = 0;
  int shutter_samples = 16;

  /// Kind::mesh: the meshes and how pixels map to their faces. Its rays move `location.z` along the face
  /// normal and reverse when `direction.z` < 0 (POV-Ray's reading of those two vectors for this camera).
  std::shared_ptr<const MeshCameraSpec> mesh;

  bool focal_blur() const { return aperture != 0 && blur_samples > 0; }
  bool motion_blur() const { return shutter_close > shutter_open; }
};

/// Makes primary rays. (sx, sy) are image-plane coordinates in [0,1]^2 with y growing downward
/// (pixel centre of column i is (i + 0.5) / width).
class Camera {
 public:
  virtual ~Camera() = default;
  /// The pinhole ray through (sx, sy) (unit direction), or nothing where the projection has no ray there
  /// (outside a fisheye's circle); POV-Ray leaves such pixels transparent black.
  virtual std::optional<math::Ray> generate_ray(double sx, double sy, double time) const = 0;
  /// Like generate_ray, but leaving from the point (lens_u, lens_v) of the lens, a point of the disc of
  /// radius 1/2 (focal blur). Rays through one image point with any lens point meet on the focal plane.
  virtual std::optional<math::Ray> generate_lens_ray(double sx, double sy, double lens_u, double lens_v,
                                                     double time) const = 0;
  /// How many rays one image point averages (a mesh camera's rays_per_pixel; 1 otherwise).
  virtual int rays_per_point() const { return 1; }
  /// Ray `ray_number` (below rays_per_point) through (sx, sy); nothing where that ray is not traced.
  virtual std::optional<math::Ray> generate_numbered_ray(double sx, double sy, int ray_number,
                                                         double time) const {
    return ray_number == 0 ? generate_ray(sx, sy, time) : std::nullopt;
  }
  /// Camera rays see nothing farther than this (a mesh camera's max_distance).
  virtual double max_distance() const;
};

/// The camera for an image of width x height pixels (only a mesh camera needs them: its faces are indexed
/// by pixel).
std::unique_ptr<Camera> make_camera(const CameraSpec& spec, int width = 1, int height = 1);

}  // namespace snell::scene
