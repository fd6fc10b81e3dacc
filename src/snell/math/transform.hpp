#pragma once
// An invertible affine transform kept together with its inverse, as POV-Ray keeps TRANSFORM {matrix,
// inverse}: objects are intersected in their own space and normals go back by the inverse transpose.
#include <optional>

#include "snell/math/bounds.hpp"
#include "snell/math/matrix4.hpp"
#include "snell/math/ray.hpp"

namespace snell::math {

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

  Vec3 point(const Vec3& p) const;
  Vec3 vector(const Vec3& v) const;
  /// Transforms a normal by the inverse transpose (not normalised).
  Vec3 normal(const Vec3& n) const;
  Vec3 inverse_point(const Vec3& p) const;
  Vec3 inverse_vector(const Vec3& v) const;
  Vec3 inverse_normal(const Vec3& n) const;
  /// The ray in the transform's source space; direction is not renormalised, so t is unchanged.
  Ray inverse_ray(const Ray& r) const { return {inverse_point(r.origin), inverse_vector(r.direction), r.time}; }
  Bounds3 bounds(const Bounds3& b) const;

  bool is_identity() const { return identity_; }
  const Matrix4& matrix() const { return m_; }
  const Matrix4& inverse_matrix() const { return inv_; }

 private:
  Matrix4 m_, inv_;
  bool identity_;
};

}  // namespace snell::math
