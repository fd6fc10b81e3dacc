// Primary rays for POV-Ray 3.7's camera types (reference "Camera", "Types of Projection", "Focal Blur").
// Each projection maps the image point to a ray exactly as POV-Ray 3.7 does: coordinates run from -1/2 to
// 1/2 across the image (or -1..1 for the fisheye-like cameras), y upward, and the non-planar projections
// use unit-length right/up/direction with their lengths folded into an aspect ratio.
#include "snell/scene/camera.hpp"

#include <cmath>

#include "snell/math/constants.hpp"
#include "snell/scene/mesh_camera.hpp"

namespace snell::scene {

namespace {

using math::Vec3;
using Kind = CameraSpec::Kind;

/// Where a primary ray starts and its (not normalised) direction, before focal blur.
struct RayStart {
  Vec3 origin;
  Vec3 direction;
};

bool uses_unit_vectors(Kind k) {
  switch (k) {
    case Kind::perspective:
    case Kind::orthographic:
    case Kind::panoramic:
    case Kind::spherical:
      return false;
    default:
      return true;
  }
}

/// Angle of image point (px, py) around the centre, as POV-Ray measures it (0 to the right, rad = |(px,
/// py)|).
double polar_phi(double px, double py, double rad) {
  if (rad <= 0) return 0;
  return px < 0 ? math::kPi - std::asin(py / rad) : std::asin(py / rad);
}

/// Rotation of v by `angle` radians about the unit axis k (Rodrigues' formula). The sense is the one POV-Ray
/// uses for its spherical camera: about `up`, a positive angle turns `direction` towards `right`.
Vec3 rotate_about(const Vec3& v, const Vec3& k, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return v * c + cross(k, v) * s + k * (dot(k, v) * (1 - c));
}

class ProjectionCamera final : public Camera {
 public:
  explicit ProjectionCamera(const CameraSpec& s) : spec_(s) {
    right_len_ = length(s.right);
    up_len_ = length(s.up);
    right_ = s.right;
    up_ = s.up;
    direction_ = s.direction;
    switch (s.kind) {
      case Kind::cylinder1:
      case Kind::cylinder3:
        aspect_ = up_len_;
        break;
      case Kind::cylinder2:
      case Kind::cylinder4:
        aspect_ = right_len_;
        break;
      case Kind::ultra_wide_angle:
        aspect_ = up_len_ / right_len_;
        break;
      default:
        aspect_ = up_len_ > 0 ? right_len_ / up_len_ : 1;
        break;
    }
    if (uses_unit_vectors(s.kind)) {
      right_ = normalize(right_);
      up_ = normalize(up_);
      direction_ = normalize(direction_);
    }
    if (s.kind == Kind::spherical) {
      right_axis_ = normalize(s.right);
      up_axis_ = normalize(s.up);
    }
    // Lens axes: a cross hair on the film plane (POV-Ray's focal blur uses up x direction and
    // direction x that, whatever the projection).
    lens_x_ = normalize(cross(s.up, s.direction));
    lens_y_ = normalize(cross(s.direction, lens_x_));
    const double dir_len = length(s.direction);
    focal_scale_ = dir_len > 0 && s.focal_distance > 0 ? s.focal_distance / dir_len : 1;
  }

  std::optional<math::Ray> generate_ray(double sx, double sy, double time) const override {
    const auto start = project(sx, sy);
    if (!start) return std::nullopt;
    return math::Ray{start->origin, normalize(start->direction), time};
  }

  std::optional<math::Ray> generate_lens_ray(double sx, double sy, double lens_u, double lens_v,
                                             double time) const override {
    const auto start = project(sx, sy);
    if (!start) return std::nullopt;
    // Move the eye across the lens and aim back at the point the pinhole ray reaches at the focal distance
    // (POV-Ray: the lens offset is aperture/2 times a point of the radius-1/2 disc).
    const double r = spec_.aperture * 0.5;
    const Vec3 shift = lens_x_ * (r * lens_u) - lens_y_ * (r * lens_v);
    const Vec3 d = start->direction * focal_scale_ - shift;
    return math::Ray{start->origin + shift, normalize(d), time};
  }

 private:
  /// The pinhole ray through image point (sx, sy); see POV-Ray 3.7's per-type formulas.
  std::optional<RayStart> project(double sx, double sy) const {
    const double x = sx - 0.5, y = 0.5 - sy;  // -1/2..1/2, y up
    const Vec3& o = spec_.location;
    const double angle = spec_.angle * math::kPi / 180;
    switch (spec_.kind) {
      case Kind::perspective:
        return RayStart{o, direction_ + x * right_ + y * up_};
      case Kind::orthographic:
        return RayStart{o + x * right_ + y * up_, direction_};
      case Kind::fisheye: {
        // Polar angle grows linearly with the distance from the centre: the image circle spans `angle`.
        const double px = 2 * x * right_len_, py = 2 * y * up_len_;
        const double rad = std::sqrt(px * px + py * py);
        if (rad > 1) return std::nullopt;
        return RayStart{o, spherical_direction(px, py, rad, rad * angle * 0.5)};
      }
      case Kind::omnimax: {
        double px = 2 * x, py = 2 * y;
        // The dome image is off-centre: the horizon sits near the bottom edge (OMNIMAX film format).
        constexpr double kOmnimaxAspect = 1.283458;
        if (aspect_ > 1) {
          if (aspect_ > kOmnimaxAspect) {
            px *= aspect_ / kOmnimaxAspect;
            py = (py - 1) / kOmnimaxAspect + 1;
          } else {
            py = (py - 1) / aspect_ + 1;
          }
        } else {
          py /= aspect_;
        }
        const double rad = std::sqrt(px * px + py * py);
        if (rad > 1) return std::nullopt;
        // The lens's radial distortion polynomial from POV-Ray.
        const double r3 = rad * rad * rad;
        const double theta = 1.411269 * rad - 0.09439 * r3 + 0.25674 * r3 * rad * rad;
        // No view more than 45 degrees below the projection axis.
        if (std::sin(polar_phi(px, py, rad)) * std::sin(theta) <
            std::tan(135.0 * math::kPi / 180) * std::cos(theta))
          return std::nullopt;
        return RayStart{o, spherical_direction(px, py, rad, theta)};
      }
      case Kind::panoramic: {
        // Graphics Gems III: longitude over 180 degrees across, latitude by tan() up and down.
        const double lon = (1 - sx) * math::kPi;
        const double lat = math::kPi * y;
        double ty;
        if (std::fabs(math::kPi / 2 - std::fabs(lat)) < 1e-10)
          ty = lat > 0 ? 2e10 : -2e10;
        else
          ty = std::tan(lat);
        return RayStart{o, std::cos(lon) * right_ + ty * up_ + std::sin(lon) * direction_};
      }
      case Kind::ultra_wide_angle: {
        const double ax = x * angle, ay = y * angle * aspect_;
        return RayStart{
            o, std::sin(ax) * right_ + std::sin(ay) * up_ + std::cos(ax) * std::cos(ay) * direction_};
      }
      case Kind::cylinder1: {
        const double a = x * angle;
        return RayStart{o, std::sin(a) * right_ + y * aspect_ * up_ + std::cos(a) * direction_};
      }
      case Kind::cylinder2: {
        const double a = y * angle;
        return RayStart{o, x * aspect_ * right_ + std::sin(a) * up_ + std::cos(a) * direction_};
      }
      case Kind::cylinder3: {
        const double a = x * angle;
        return RayStart{o + y * aspect_ * up_, std::sin(a) * right_ + std::cos(a) * direction_};
      }
      case Kind::cylinder4: {
        const double a = y * angle;
        return RayStart{o + x * aspect_ * right_, std::sin(a) * up_ + std::cos(a) * direction_};
      }
      case Kind::mesh:
        return std::nullopt;  // MeshCamera makes these
      case Kind::spherical: {
        // Latitude first (about right), then longitude (about up).
        const double lat = y * spec_.v_angle * math::kPi / 180;
        const double lon = x * spec_.h_angle * math::kPi / 180;
        return RayStart{o, rotate_about(rotate_about(direction_, right_axis_, -lat), up_axis_, lon)};
      }
    }
    return std::nullopt;
  }

  /// Direction at polar angle theta from `direction`, turned towards the image point (px, py) at distance
  /// rad from the centre (fisheye and omnimax).
  Vec3 spherical_direction(double px, double py, double rad, double theta) const {
    const double phi = polar_phi(px, py, rad);
    const double st = std::sin(theta);
    return (std::cos(phi) * st) * right_ + (std::sin(phi) * st) * up_ + std::cos(theta) * direction_;
  }

  CameraSpec spec_;
  Vec3 right_, up_, direction_;
  Vec3 right_axis_, up_axis_;
  Vec3 lens_x_, lens_y_;
  double right_len_ = 1, up_len_ = 1, aspect_ = 1;
  double focal_scale_ = 1;
};

/// A mesh_camera; focal blur does not apply (its lens point is ignored).
class MeshCamera final : public Camera {
 public:
  MeshCamera(const CameraSpec& s, int width, int height)
      : rays_(*s.mesh, s.location.z, s.direction.z < -kMeshReverseEpsilon, width, height),
        max_distance_(s.mesh->max_distance > 0 ? s.mesh->max_distance : math::kInfinity) {}

  std::optional<math::Ray> generate_ray(double sx, double sy, double time) const override {
    return generate_numbered_ray(sx, sy, 0, time);
  }
  std::optional<math::Ray> generate_lens_ray(double sx, double sy, double, double,
                                             double time) const override {
    return generate_numbered_ray(sx, sy, 0, time);
  }
  int rays_per_point() const override { return rays_.rays_per_pixel(); }
  std::optional<math::Ray> generate_numbered_ray(double sx, double sy, int ray_number,
                                                 double time) const override {
    auto ray = rays_.ray(sx, sy, ray_number, time);
    if (!ray || length_squared(ray->direction) == 0) return std::nullopt;
    ray->direction = normalize(ray->direction);
    return ray;
  }
  double max_distance() const override { return max_distance_; }

 private:
  /// POV-Ray's EPSILON: direction.z below -EPSILON reverses the rays.
  static constexpr double kMeshReverseEpsilon = 1e-10;
  MeshCameraRays rays_;
  double max_distance_;
};

}  // namespace

double Camera::max_distance() const {
  return math::kInfinity;
}

std::unique_ptr<Camera> make_camera(const CameraSpec& spec, int width, int height) {
  if (spec.kind == Kind::mesh && spec.mesh) return std::make_unique<MeshCamera>(spec, width, height);
  return std::make_unique<ProjectionCamera>(spec);
}

}  // namespace snell::scene
