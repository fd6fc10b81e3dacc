#pragma once
// POV-Ray `bicubic_patch` (POV-Ray 3.7 reference, "Bicubic Patch"): a Bezier patch of 4 x 4 control points,
// listed row by row, u along a row and v down the columns. snell always tessellates it, as POV-Ray's type 1
// does: 2^u_steps x 2^v_steps quads of two triangles with normals from the patch's derivatives.
#include <array>

#include "snell/geometry/mesh.hpp"

namespace snell::geometry {

using BezierPoints = std::array<Vec3, 16>;

/// The patch point at (u, v) in [0, 1]^2, and its partial derivatives when wanted.
Vec3 bezier_patch_point(const BezierPoints& p, double u, double v, Vec3* du = nullptr, Vec3* dv = nullptr);

/// Triangles of the patch, with smooth normals and (u, v) texture coordinates. Steps are clamped to 0..8.
MeshData tessellate_bicubic_patch(const BezierPoints& points, int u_steps, int v_steps);

}  // namespace snell::geometry
