#include "snell/texture/mapping_warps.hpp"

#include <cmath>

#include "snell/math/constants.hpp"
#include "snell/texture/lattice_hash.hpp"

namespace snell::texture {

namespace {

double component(const Vec3& v, int axis) {
  return axis == 0 ? v.x : axis == 1 ? v.y : v.z;
}

double& component(Vec3& v, int axis) {
  return axis == 0 ? v.x : axis == 1 ? v.y : v.z;
}

/// The angle of (x, z) from +x, turning toward +z, as a fraction of a full turn in [0, 1).
double turn_fraction(double x, double z, double length) {
  double theta = std::acos(std::clamp(x / length, -1.0, 1.0));
  if (z < 0) theta = 2 * math::kPi - theta;
  if (z == 0) theta = x > 0 ? 0 : math::kPi;
  return theta / (2 * math::kPi);
}

/// Places the wrapped point (u, v, w) so that w runs along `orientation` (the identity for +z), as
/// POV-Ray's mapping warps orient their result.
Vec3 orient(const Vec3& o, double u, double v, double w) {
  if (o.x == 0 && o.y == 0 && o.z == 1) return {u, v, w};
  return {o.x * w + o.y * u + o.z * u, o.x * v - o.y * w + o.z * v, -o.x * u + o.y * v + o.z * w};
}

}  // namespace

Vec3 BlackHoleWarp::warp(const Vec3& p) const {
  const BlackHoleParams& b = params_;
  Vec3 center = b.center;
  const bool repeated = b.repeat.x > 0 || b.repeat.y > 0 || b.repeat.z > 0;
  if (repeated) {
    int cell[3] = {0, 0, 0};
    for (int axis = 0; axis < 3; ++axis) {
      const double size = component(b.repeat, axis);
      if (size > 1e-10) cell[axis] = static_cast<int>(std::floor(component(p, axis) / size));
    }
    for (int axis = 0; axis < 3; ++axis) {
      // Each cell's hole is moved by its own fixed amount in [-1, 1] times the jitter.
      const double r = 2 * lattice_random(cell[0], cell[1], cell[2], static_cast<uint32_t>(axis)) - 1;
      component(center, axis) += r * component(b.jitter, axis) + component(b.repeat, axis) * cell[axis];
    }
  }
  const Vec3 delta = p - center;
  const double distance = math::length(delta);
  if (distance >= b.radius) return p;
  // 0 on the rim, 1 at the centre; raised to the falloff and scaled by the strength, capped at 1 so no
  // point moves past the centre.
  const double pull = std::min(std::pow((b.radius - distance) / b.radius, b.falloff) * b.strength, 1.0);
  return p + delta * (b.inverse ? -pull : pull);
}

Vec3 RepeatWarp::warp(const Vec3& p) const {
  const double block = std::floor(component(p, axis_) / width_);
  Vec3 q = p;
  component(q, axis_) -= block * width_;
  if (static_cast<long long>(block) & 1) {
    q = {q.x * flip_.x, q.y * flip_.y, q.z * flip_.z};
    if (component(flip_, axis_) < 0) component(q, axis_) += width_;
  }
  return q + block * offset_;
}

Vec3 MappingWarp::warp(const Vec3& p) const {
  const Params& m = params_;
  const auto scale_by_distance = [&](double distance) {
    return m.dist_exp == 0 ? 1.0 : m.dist_exp == 1 ? distance : std::pow(distance, m.dist_exp);
  };
  switch (m.kind) {
    case Kind::planar:
      return orient(m.orientation, p.x, p.y, m.offset);
    case Kind::cylindrical: {
      const double radius = std::hypot(p.x, p.z);
      if (radius == 0) return p;
      const double u = turn_fraction(p.x, p.z, radius) * scale_by_distance(radius);
      return orient(m.orientation, u, p.y, radius);
    }
    case Kind::spherical: {
      const double distance = math::length(p);
      if (distance == 0) return p;
      const Vec3 d = p / distance;
      const double radius = std::hypot(d.x, d.z);
      const double u = radius == 0 ? 0 : turn_fraction(d.x, d.z, radius);
      const double v = 0.5 + std::asin(std::clamp(d.y, -1.0, 1.0)) / math::kPi;
      const double k = scale_by_distance(distance);
      return orient(m.orientation, u * k, v * k, distance);
    }
    case Kind::toroidal: {
      const double radius = std::hypot(p.x, p.z);
      if (radius == 0) return p;
      const double u = turn_fraction(p.x, p.z, radius);
      // The point's place around the tube, measured in the plane through the y axis.
      const double across = radius - m.major_radius;
      const double tube = std::hypot(across, p.y);
      double phi = tube == 0 ? 0 : std::acos(std::clamp(-across / tube, -1.0, 1.0));
      if (p.y > 0) phi = 2 * math::kPi - phi;
      const double k = scale_by_distance(tube);
      return orient(m.orientation, u * k, phi / (2 * math::kPi) * k, tube);
    }
  }
  return p;
}

}  // namespace snell::texture
