#include "snell/geometry/bicubic_patch.hpp"

#include <algorithm>

namespace snell::geometry {

namespace {

/// Cubic Bernstein polynomials at t and their derivatives.
void bernstein(double t, double b[4], double d[4]) {
  const double s = 1 - t;
  b[0] = s * s * s, b[1] = 3 * t * s * s, b[2] = 3 * t * t * s, b[3] = t * t * t;
  d[0] = -3 * s * s, d[1] = 3 * s * s - 6 * t * s, d[2] = 6 * t * s - 3 * t * t, d[3] = 3 * t * t;
}

}  // namespace

Vec3 bezier_patch_point(const BezierPoints& p, double u, double v, Vec3* du, Vec3* dv) {
  double bu[4], bv[4], du_w[4], dv_w[4];
  bernstein(u, bu, du_w);
  bernstein(v, bv, dv_w);
  Vec3 point, d_u, d_v;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const Vec3& c = p[static_cast<std::size_t>(4 * i + j)];
      point += bv[i] * bu[j] * c;
      d_u += bv[i] * du_w[j] * c;
      d_v += dv_w[i] * bu[j] * c;
    }
  if (du) *du = d_u;
  if (dv) *dv = d_v;
  return point;
}

MeshData tessellate_bicubic_patch(const BezierPoints& points, int u_steps, int v_steps) {
  const int nu = 1 << std::clamp(u_steps, 0, 8), nv = 1 << std::clamp(v_steps, 0, 8);
  MeshData mesh;
  for (int i = 0; i <= nv; ++i)
    for (int j = 0; j <= nu; ++j) {
      const double u = static_cast<double>(j) / nu, v = static_cast<double>(i) / nv;
      Vec3 du, dv;
      mesh.vertices.push_back(bezier_patch_point(points, u, v, &du, &dv));
      Vec3 n = cross(du, dv);
      if (!(length_squared(n) > 0)) {
        // A collapsed edge (several equal control points): step inwards to find the normal.
        const double uu = std::clamp(u, 1e-4, 1 - 1e-4), vv = std::clamp(v, 1e-4, 1 - 1e-4);
        bezier_patch_point(points, uu, vv, &du, &dv);
        n = cross(du, dv);
      }
      mesh.normals.push_back(n);
      mesh.uvs.push_back({u, v});
    }
  const auto index = [&](int i, int j) { return i * (nu + 1) + j; };
  for (int i = 0; i < nv; ++i)
    for (int j = 0; j < nu; ++j) {
      const std::array<int, 3> a{index(i, j), index(i, j + 1), index(i + 1, j)};
      const std::array<int, 3> b{index(i + 1, j + 1), index(i + 1, j), index(i, j + 1)};
      for (const auto& face : {a, b}) {
        // Skip triangles that collapse to a line or point (patches with coincident control points).
        const Vec3& p0 = mesh.vertices[static_cast<std::size_t>(face[0])];
        if (length_squared(cross(mesh.vertices[static_cast<std::size_t>(face[1])] - p0,
                                 mesh.vertices[static_cast<std::size_t>(face[2])] - p0)) == 0)
          continue;
        mesh.faces.push_back(face);
        mesh.normal_indices.push_back(face);
        mesh.uv_indices.push_back(face);
      }
    }
  return mesh;
}

}  // namespace snell::geometry
