#include "snell/math/transform.hpp"

#include <algorithm>
#include <cmath>

#include "snell/math/constants.hpp"

namespace snell::math {


std::optional<Transform> Transform::from_matrix(const Matrix4& m) {
  auto inv = m.inverse();
  if (!inv) return std::nullopt;
  return Transform(m, *inv);
}

Transform Transform::translate(const Vec3& d) {
  Matrix4 m = Matrix4::identity(), inv = Matrix4::identity();
  for (int i = 0; i < 3; ++i) {
    m.m[i][3] = d[i];
    inv.m[i][3] = -d[i];
  }
  return Transform(m, inv);
}

Transform Transform::scale(const Vec3& s) {
  Matrix4 m = Matrix4::identity(), inv = Matrix4::identity();
  for (int i = 0; i < 3; ++i) {
    m.m[i][i] = s[i];
    inv.m[i][i] = 1.0 / s[i];
  }
  return Transform(m, inv);
}

Transform Transform::rotate_xyz_degrees(const Vec3& degrees) {
  // POV-Ray (math/matrices.cpp, Compute_Rotation_Transform) rotates about x, then y, then z; each is the
  // ordinary right-hand-rule matrix of the axis, which in POV-Ray's left-handed frame looks clockwise
  // when viewed from the positive axis (the "left-hand rule" of the POV-Ray documentation).
  Transform result;
  for (int axis = 0; axis < 3; ++axis) {
    if (degrees[axis] == 0) continue;
    const double a = radians(degrees[axis]);
    const double c = std::cos(a), s = std::sin(a);
    Matrix4 r = Matrix4::identity();
    const int i = (axis + 1) % 3, j = (axis + 2) % 3;
    r.m[i][i] = c;
    r.m[i][j] = -s;
    r.m[j][i] = s;
    r.m[j][j] = c;
    result = Transform(r, r.transposed()) * result;
  }
  return result;
}

Transform Transform::rotate_axis_degrees(const Vec3& axis_in, double degrees) {
  const Vec3 k = normalize(axis_in);
  const double a = radians(degrees);
  const double c = std::cos(a), s = std::sin(a), t = 1 - c;
  Matrix4 r = Matrix4::identity();
  // Rodrigues' rotation formula.
  r.m[0][0] = t * k.x * k.x + c;
  r.m[0][1] = t * k.x * k.y - s * k.z;
  r.m[0][2] = t * k.x * k.z + s * k.y;
  r.m[1][0] = t * k.x * k.y + s * k.z;
  r.m[1][1] = t * k.y * k.y + c;
  r.m[1][2] = t * k.y * k.z - s * k.x;
  r.m[2][0] = t * k.x * k.z - s * k.y;
  r.m[2][1] = t * k.y * k.z + s * k.x;
  r.m[2][2] = t * k.z * k.z + c;
  return Transform(r, r.transposed());
}

std::optional<Transform> Transform::pov_matrix(const double v[12]) {
  Matrix4 m = Matrix4::identity();
  for (int row = 0; row < 4; ++row)
    for (int col = 0; col < 3; ++col) m.m[col][row] = v[row * 3 + col];
  return from_matrix(m);
}

Transform Transform::operator*(const Transform& o) const {
  if (identity_) return o;
  if (o.identity_) return *this;
  return Transform(m_ * o.m_, o.inv_ * inv_);
}


Bounds3 Transform::bounds(const Bounds3& b) const {
  if (identity_ || b.empty()) return b;
  if (b.is_finite()) {
    Bounds3 r;
    for (int i = 0; i < 8; ++i)
      r.unite(point({(i & 1) ? b.hi.x : b.lo.x, (i & 2) ? b.hi.y : b.lo.y, (i & 4) ? b.hi.z : b.lo.z}));
    return r;
  }
  // A box unbounded on some axes (a half-space, an infinite cylinder): each output axis is the sum of the
  // intervals m_ij [lo_j, hi_j] (Arvo, "Transforming axis-aligned bounding boxes", Graphics Gems 1990),
  // where a zero coefficient takes nothing from an infinite side instead of 0 * inf.
  Bounds3 r;
  for (int i = 0; i < 3; ++i) {
    double lo = m_.m[i][3], hi = m_.m[i][3];
    for (int j = 0; j < 3; ++j) {
      const double c = m_.m[i][j];
      if (c == 0) continue;
      const double a = c * b.lo[j], e = c * b.hi[j];
      lo += std::min(a, e);
      hi += std::max(a, e);
    }
    r.lo[i] = lo;
    r.hi[i] = hi;
  }
  return r;
}

}  // namespace snell::math
