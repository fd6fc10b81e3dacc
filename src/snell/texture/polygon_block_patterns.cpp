#include "snell/texture/polygon_block_patterns.hpp"

#include <cmath>

namespace snell::texture {

namespace {

/// n mod m in [0, m) for negative n too.
int wrap(long long n, int m) {
  const int r = static_cast<int>(n % m);
  return r < 0 ? r + m : r;
}

}  // namespace

int SquarePattern::block(const Vec3& p) const {
  const bool odd_x = wrap(static_cast<long long>(std::floor(p.x)), 2) == 1;
  const bool odd_z = wrap(static_cast<long long>(std::floor(p.z)), 2) == 1;
  // The numbering POV-Ray's square pattern gives (pattern.cpp): (even, even) 0, (even, odd) 1,
  // (odd, odd) 2, (odd, even) 3 for (x, z).
  if (odd_x) return odd_z ? 2 : 3;
  return odd_z ? 1 : 0;
}

int TriangularPattern::block(const Vec3& p) const {
  // Rows of height h = sqrt(3)/2 along z. In each row, triangles with their base on the row's lower
  // edge alternate with triangles whose base is on its upper edge; at height fraction t a lower-based
  // triangle of centre c covers |x - c| <= (1 - t) / 2. In even rows the lower-based triangles sit at
  // half-integer x, in odd rows at integer x. The entry numbers reproduce POV-Ray's (pattern.cpp
  // TriangularPattern): even row, lower-based at k + 1/2: -2k mod 6, upper-based at k: 2k + 1 mod 6; an
  // odd row takes 5 minus the entry of the triangle it mirrors.
  const double h = std::sqrt(3.0) / 2;
  const double row_position = p.z / h;
  const double row = std::floor(row_position);
  const double t = row_position - row;
  const bool odd_row = wrap(static_cast<long long>(row), 2) == 1;
  const double lower_offset = odd_row ? 0.0 : 0.5;
  const double nearest = std::floor(p.x - lower_offset + 0.5);
  const bool lower_based = std::fabs(p.x - lower_offset - nearest) <= (1 - t) / 2;
  // The triangle's centre as k (integer centres) or k + 1/2 (half-integer centres).
  const double centre =
      lower_based ? nearest + lower_offset : std::floor(p.x + lower_offset) + (0.5 - lower_offset);
  const long long k = static_cast<long long>(std::floor(centre));
  const bool integer_centre = centre == std::floor(centre);
  const int even_row_entry = integer_centre ? wrap(2 * k + 1, 6) : wrap(-2 * k, 6);
  return odd_row ? 5 - even_row_entry : even_row_entry;
}

int CubicPattern::block(const Vec3& p) const {
  // The face of the axis with the largest |coordinate|; on ties the positive faces win over the
  // negative ones, x over y over z (the order of POV-Ray's tests, pattern.cpp CubicPattern).
  const double c[3] = {p.x, p.y, p.z};
  const double a[3] = {std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)};
  for (int sign = 0; sign < 2; ++sign)
    for (int i = 0; i < 3; ++i) {
      const bool facing = sign == 0 ? c[i] >= 0 : c[i] < 0;
      if (facing && a[i] >= a[(i + 1) % 3] && a[i] >= a[(i + 2) % 3]) return i + 3 * sign;
    }
  return 5;
}

std::shared_ptr<const BlockPattern> make_polygon_block_pattern(const std::string& name) {
  if (name == "square") return std::make_shared<SquarePattern>();
  if (name == "triangular") return std::make_shared<TriangularPattern>();
  if (name == "cubic") return std::make_shared<CubicPattern>();
  return nullptr;
}

}  // namespace snell::texture
