#include "snell/math/matrix4.hpp"

#include <cmath>
#include <utility>

namespace snell::math {

Matrix4 Matrix4::identity() {
  Matrix4 r;
  for (int i = 0; i < 4; ++i) r.m[i][i] = 1;
  return r;
}

Matrix4 Matrix4::operator*(const Matrix4& o) const {
  Matrix4 r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      double s = 0;
      for (int k = 0; k < 4; ++k) s += m[i][k] * o.m[k][j];
      r.m[i][j] = s;
    }
  return r;
}

Matrix4 Matrix4::transposed() const {
  Matrix4 r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) r.m[i][j] = m[j][i];
  return r;
}

std::optional<Matrix4> Matrix4::inverse() const {
  Matrix4 a = *this;
  Matrix4 inv = identity();
  // Scale-aware singularity threshold: the largest entry times a few ulps.
  double largest = 0;
  for (const auto& row : m)
    for (double v : row) largest = std::max(largest, std::fabs(v));
  const double tiny = largest * 1e-14;
  for (int col = 0; col < 4; ++col) {
    int pivot = col;
    for (int r = col + 1; r < 4; ++r)
      if (std::fabs(a.m[r][col]) > std::fabs(a.m[pivot][col])) pivot = r;
    if (!(std::fabs(a.m[pivot][col]) > tiny)) return std::nullopt;
    std::swap(a.m[pivot], a.m[col]);
    std::swap(inv.m[pivot], inv.m[col]);
    const double scale = 1.0 / a.m[col][col];
    for (int j = 0; j < 4; ++j) {
      a.m[col][j] *= scale;
      inv.m[col][j] *= scale;
    }
    for (int r = 0; r < 4; ++r) {
      if (r == col) continue;
      const double f = a.m[r][col];
      if (f == 0) continue;
      for (int j = 0; j < 4; ++j) {
        a.m[r][j] -= f * a.m[col][j];
        inv.m[r][j] -= f * inv.m[col][j];
      }
    }
  }
  return inv;
}

}  // namespace snell::math
