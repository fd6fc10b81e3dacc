#pragma once
// Pieces shared by the shapes built around an axis frame (u, v, w) from a base point: cylinder and cone.
// Rays arrive already expressed in that frame (o, d), with the axis running from z = 0 to z = length.
#include "snell/geometry/hit_buffer.hpp"
#include "snell/geometry/shape.hpp"

namespace snell::geometry {

/// Adds the flat end discs at z = 0 (radius r0, normal -w) and z = length (radius r1, normal +w); a zero
/// radius is a pointed end and has no disc. Parts 1 and 2 name the ends.
template <typename Buffer>
void add_end_caps(const Vec3& o, const Vec3& d, double length, double r0, double r1, const Vec3& w,
                  Buffer& hits) {
  if (d.z == 0) return;
  for (int end = 0; end < 2; ++end) {
    const double r = end == 0 ? r0 : r1;
    if (r == 0) continue;
    const double t = ((end == 0 ? 0.0 : length) - o.z) / d.z;
    if (!hits.accepts(t)) continue;
    const Vec3 p = o + t * d;
    if (p.x * p.x + p.y * p.y > r * r) continue;
    LocalHit h;
    h.t = t;
    h.normal = end == 0 ? -w : w;
    h.uv = {0.5 + 0.5 * p.x / r, 0.5 + 0.5 * p.y / r};
    h.part = 1 + end;
    hits.add(h);
  }
}

}  // namespace snell::geometry
