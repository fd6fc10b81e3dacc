#pragma once
// An invertible affine transform kept together with its inverse, as POV-Ray keeps TRANSFORM {matrix,
// inverse}: objects are intersected in their own space and normals go back by the inverse transpose.
#include <optional>

#include "snell/math/bounds.hpp"
#include "snell/math/matrix4.hpp"
#include "snell/math/ray.hpp"

namespace snell::math {

// Inline: every ray meets them once or twice per object it is tested against.
inline Vec3 apply_point(const Matrix4& a, const Vec3& p) {
  const auto& m = a.m;
  return {m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3],
          m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3],
          m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3]};
}
inline Vec3 apply_vector(const Matrix4& a, const Vec3& v) {
  const auto& m = a.m;
  return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z, m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
          m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
}
inline Vec3 apply_transposed_vector(const Matrix4& a, const Vec3& v) {
  const auto& m = a.m;
  return {m[0][0] * v.x + m[1][0] * v.y + m[2][0] * v.z, m[0][1] * v.x + m[1][1] * v.y + m[2][1] * v.z,
          m[0][2] * v.x + m[1][2] * v.y + m[2][2] * v.z};
}

class Transform {
 public:
  Transform() : m_(Matrix4::identity()), inv_(Matrix4::identity()), identity_(true) {}
  Transform(const Matrix4& m, const Matrix4& inv) : m_(m), inv_(inv), identity_(m.is_identity()) {}

  /// nullopt when `m` is singular (the parser reports that with the scene location).
  static std::optional<Transform> from_matrix(const Matrix4& m);
  static Transform translate(const Vec3& d);
  /// Non-uniform scale; each factor must be non-zero (callers validate).
  static Transform scale(const Vec3& s);
  /// POV-Ray's `rotate <a,b,c>`: degrees about x, then y, then z.
  static Transform rotate_xyz_degrees(const Vec3& degrees);
  /// Rotation by `degrees` about an arbitrary unit `axis` (POV-Ray's `axis_rotate`, vaxis_rotate).
  static Transform rotate_axis_degrees(const Vec3& axis, double degrees);
  /// POV-Ray's 12-value `matrix <...>` (row-vector convention: rows are x', y', z' images and translation).
  static std::optional<Transform> pov_matrix(const double values[12]);

  /// `a * b` applies b first, then a.
  Transform operator*(const Transform& o) const;
  Transform inverse() const { return Transform(inv_, m_); }

  Vec3 point(const Vec3& p) const { return identity_ ? p : apply_point(m_, p); }
  Vec3 vector(const Vec3& v) const { return identity_ ? v : apply_vector(m_, v); }
  /// Transforms a normal by the inverse transpose (not normalised).
  Vec3 normal(const Vec3& n) const { return identity_ ? n : apply_transposed_vector(inv_, n); }
  Vec3 inverse_point(const Vec3& p) const { return identity_ ? p : apply_point(inv_, p); }
  Vec3 inverse_vector(const Vec3& v) const { return identity_ ? v : apply_vector(inv_, v); }
  Vec3 inverse_normal(const Vec3& n) const { return identity_ ? n : apply_transposed_vector(m_, n); }
  /// The ray in the transform's source space; direction is not renormalised, so t is unchanged.
  Ray inverse_ray(const Ray& r) const {
    return {inverse_point(r.origin), inverse_vector(r.direction), r.time};
  }
  Bounds3 bounds(const Bounds3& b) const;

  bool is_identity() const { return identity_; }
  /// The factors of a transform that only scales along the axes (by positive factors) and translates;
  /// nullopt for any other (rotations, shears, mirrors).
  std::optional<Vec3> axis_scale() const {
    const auto& m = m_.m;
    if (m[0][1] != 0 || m[0][2] != 0 || m[1][0] != 0 || m[1][2] != 0 || m[2][0] != 0 || m[2][1] != 0)
      return std::nullopt;
    if (!(m[0][0] > 0 && m[1][1] > 0 && m[2][2] > 0)) return std::nullopt;
    return Vec3{m[0][0], m[1][1], m[2][2]};
  }
  /// The factor of a transform that scales uniformly (by a positive factor) and translates, else nullopt.
  std::optional<double> uniform_scale() const {
    const auto s = axis_scale();
    if (!s || s->x != s->y || s->x != s->z) return std::nullopt;
    return s->x;
  }
  const Matrix4& matrix() const { return m_; }
  const Matrix4& inverse_matrix() const { return inv_; }

 private:
  Matrix4 m_, inv_;
  bool identity_;
};

}  // namespace snell::math
