#pragma once
#include <array>
#include <optional>

#include "snell/math/vec3.hpp"

namespace snell::math {

/// Row-major 4x4 matrix acting on column vectors: p' = M p.
struct Matrix4 {
  std::array<std::array<double, 4>, 4> m{};

  static Matrix4 identity();
  bool operator==(const Matrix4&) const = default;
  Matrix4 operator*(const Matrix4& o) const;
  Matrix4 transposed() const;
  /// Gauss-Jordan inverse with partial pivoting; nullopt when singular (e.g. `scale 0`).
  std::optional<Matrix4> inverse() const;
  bool is_identity() const { return *this == identity(); }
};

}  // namespace snell::math
