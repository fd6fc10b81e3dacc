#include "snell/geometry/height_field.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "snell/geometry/triangle_kernel.hpp"
#include "snell/math/constants.hpp"

namespace snell::geometry {

// Grid space: x = i, z = k, y unchanged; shape space divides x by (width - 1) and z by (depth - 1). Rays
// are scaled into grid space, which keeps t.

HeightField::HeightField(HeightGrid grid, bool smooth, double water_level)
    : grid_(std::move(grid)), smooth_(smooth), water_(water_level) {
  if (grid_.width < 2 || grid_.depth < 2)
    throw std::invalid_argument("height_field: needs at least 2 x 2 samples");
  if (grid_.heights.size() != static_cast<std::size_t>(grid_.width) * static_cast<std::size_t>(grid_.depth))
    throw std::invalid_argument("height_field: sample count does not match its size");
  const float water = static_cast<float>(water_);
  for (float& v : grid_.heights) v = std::max(v, water);
  const int cw = grid_.width - 1, cd = grid_.depth - 1;
  cell_lo_.resize(static_cast<std::size_t>(cw) * static_cast<std::size_t>(cd));
  cell_hi_.resize(cell_lo_.size());
  blocks_w_ = (cw + kBlock - 1) / kBlock;
  const int blocks_d = (cd + kBlock - 1) / kBlock;
  block_lo_.assign(static_cast<std::size_t>(blocks_w_) * static_cast<std::size_t>(blocks_d), INFINITY);
  block_hi_.assign(block_lo_.size(), -INFINITY);
  y_lo_ = math::kInfinity, y_hi_ = -math::kInfinity;
  for (int k = 0; k < cd; ++k)
    for (int i = 0; i < cw; ++i) {
      const float a = h(i, k), b = h(i + 1, k), c = h(i, k + 1), d = h(i + 1, k + 1);
      const std::size_t cell =
          static_cast<std::size_t>(k) * static_cast<std::size_t>(cw) + static_cast<std::size_t>(i);
      cell_lo_[cell] = std::min({a, b, c, d});
      cell_hi_[cell] = std::max({a, b, c, d});
      y_lo_ = std::min(y_lo_, cell_lo_[cell]);
      y_hi_ = std::max(y_hi_, cell_hi_[cell]);
      const std::size_t block = static_cast<std::size_t>(k / kBlock) * static_cast<std::size_t>(blocks_w_) +
                                static_cast<std::size_t>(i / kBlock);
      block_lo_[block] = std::min(block_lo_[block], cell_lo_[cell]);
      block_hi_[block] = std::max(block_hi_[block], cell_hi_[cell]);
    }
}

Bounds3 HeightField::bounds() const {
  // The solid reaches down to y = 0 (or the water level) as POV-Ray's bounding box does.
  return {Vec3(0, std::min(0.0f, y_lo_), 0), Vec3(1, y_hi_, 1)};
}

Vec3 HeightField::vertex_normal(int i, int k) const {
  // Central differences of the samples (one-sided at the border), in grid space.
  const int i0 = std::max(i - 1, 0), i1 = std::min(i + 1, grid_.width - 1);
  const int k0 = std::max(k - 1, 0), k1 = std::min(k + 1, grid_.depth - 1);
  return {(h(i0, k) - h(i1, k)) / (i1 - i0), 1.0, (h(i, k0) - h(i, k1)) / (k1 - k0)};
}

int HeightField::cell_hits(const Ray& grid_ray, int i, int k, double t0, double t1, LocalHit out[2]) const {
  const double x0 = i, x1 = i + 1, z0 = k, z1 = k + 1;
  // The two triangles of POV-Ray's split, each with corners listed so the normal points up.
  struct Tri {
    Vec3 a, b, c;
    int ia, ka, ib, kb, ic, kc;
  };
  const Tri tris[2] = {
      {{x0, h(i, k), z0}, {x0, h(i, k + 1), z1}, {x1, h(i + 1, k), z0}, i, k, i, k + 1, i + 1, k},
      {{x1, h(i + 1, k + 1), z1},
       {x1, h(i + 1, k), z0},
       {x0, h(i, k + 1), z1},
       i + 1,
       k + 1,
       i + 1,
       k,
       i,
       k + 1},
  };
  const float water = static_cast<float>(water_);
  int n = 0;
  for (const Tri& tri : tris) {
    if (tri.a.y <= water && tri.b.y <= water && tri.c.y <= water && water > 0) continue;
    TriangleHit th;
    if (!intersect_triangle(tri.a, tri.b, tri.c, grid_ray, t0, t1, th)) continue;
    LocalHit& hit = out[n++];
    hit = LocalHit{};
    hit.t = th.t;
    const Vec3 g = cross(tri.b - tri.a, tri.c - tri.a);
    // Grid-space normals go to shape space by the inverse transpose of the scaling: multiply x, z.
    const Vec3 to_shape(grid_.width - 1, 1, grid_.depth - 1);
    hit.normal = g * to_shape;
    if (smooth_) {
      const Vec3 s = (1 - th.b1 - th.b2) * vertex_normal(tri.ia, tri.ka) +
                     th.b1 * vertex_normal(tri.ib, tri.kb) + th.b2 * vertex_normal(tri.ic, tri.kc);
      hit.shading_normal = s * to_shape;
    }
    const Vec3 p = grid_ray.at(th.t);
    hit.uv = {p.x / (grid_.width - 1), p.z / (grid_.depth - 1)};
  }
  if (n == 2 && out[1].t < out[0].t) std::swap(out[0], out[1]);
  return n;
}

template <typename Sink>
void HeightField::walk(const Ray& ray, double t_min, double t_max, Sink&& sink) const {
  const double sx = grid_.width - 1, sz = grid_.depth - 1;
  const Ray g{{ray.origin.x * sx, ray.origin.y, ray.origin.z * sz},
              {ray.direction.x * sx, ray.direction.y, ray.direction.z * sz},
              ray.time};
  // Clip to the grid's box (slabs).
  const Vec3 lo(0, y_lo_, 0), hi(sx, y_hi_, sz);
  double t0 = t_min, t1 = t_max;
  for (int a = 0; a < 3; ++a) {
    const double d = g.direction[a], o = g.origin[a];
    if (d == 0) {
      if (o < lo[a] || o > hi[a]) return;
      continue;
    }
    double ta = (lo[a] - o) / d, tb = (hi[a] - o) / d;
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta), t1 = std::min(t1, tb);
  }
  if (!(t0 <= t1)) return;

  // 2D DDA over the cells in x and z.
  const Vec3 start = g.at(t0);
  int i = std::clamp(static_cast<int>(std::floor(start.x)), 0, grid_.width - 2);
  int k = std::clamp(static_cast<int>(std::floor(start.z)), 0, grid_.depth - 2);
  const int step_i = g.direction.x > 0 ? 1 : -1, step_k = g.direction.z > 0 ? 1 : -1;
  const auto next_boundary = [&](double o, double d, int cell, int step) {
    if (d == 0) return math::kInfinity;
    return ((step > 0 ? cell + 1 : cell) - o) / d;
  };
  double next_x = next_boundary(g.origin.x, g.direction.x, i, step_i);
  double next_z = next_boundary(g.origin.z, g.direction.z, k, step_k);
  const double dx = g.direction.x != 0 ? step_i / g.direction.x : math::kInfinity;
  const double dz = g.direction.z != 0 ? step_k / g.direction.z : math::kInfinity;
  const int cells_w = grid_.width - 1, cells_d = grid_.depth - 1;
  double ta = t0;
  int block_i = -1, block_k = -1;
  for (;;) {
    if (i / kBlock != block_i || k / kBlock != block_k) {
      // A new block: if the ray passes above or below all of it, go straight to the cell beyond it.
      block_i = i / kBlock, block_k = k / kBlock;
      const double exit_x =
          next_boundary(g.origin.x, g.direction.x, block_i * kBlock + (step_i > 0 ? kBlock - 1 : 0), step_i);
      const double exit_z =
          next_boundary(g.origin.z, g.direction.z, block_k * kBlock + (step_k > 0 ? kBlock - 1 : 0), step_k);
      const double te = std::min({exit_x, exit_z, t1});
      const double ya = g.origin.y + ta * g.direction.y, ye = g.origin.y + te * g.direction.y;
      const std::size_t block = static_cast<std::size_t>(block_k) * static_cast<std::size_t>(blocks_w_) +
                                static_cast<std::size_t>(block_i);
      // A margin over the rounding of the heights along the ray, which the cells' own tests compute at
      // other parameters.
      const double slack = 1e-9 * (std::fabs(ya) + std::fabs(ye) + 1);
      if (std::min(ya, ye) > block_hi_[block] + slack || std::max(ya, ye) < block_lo_[block] - slack) {
        if (te >= t1) return;
        const auto clamp_to_block = [](double v, int block_start, int cells) {
          return std::clamp(static_cast<int>(std::floor(v)), block_start,
                            std::min(block_start + kBlock, cells) - 1);
        };
        const Vec3 at = g.at(te);
        if (exit_x <= exit_z) {
          i = step_i > 0 ? (block_i + 1) * kBlock : block_i * kBlock - 1;
          k = clamp_to_block(at.z, block_k * kBlock, cells_d);
        } else {
          k = step_k > 0 ? (block_k + 1) * kBlock : block_k * kBlock - 1;
          i = clamp_to_block(at.x, block_i * kBlock, cells_w);
        }
        if (i < 0 || i >= cells_w || k < 0 || k >= cells_d) return;
        next_x = next_boundary(g.origin.x, g.direction.x, i, step_i);
        next_z = next_boundary(g.origin.z, g.direction.z, k, step_k);
        ta = te;
        continue;
      }
    }
    const double tb = std::min({next_x, next_z, t1});
    const std::size_t cell =
        static_cast<std::size_t>(k) * static_cast<std::size_t>(cells_w) + static_cast<std::size_t>(i);
    const double ya = g.origin.y + ta * g.direction.y, yb = g.origin.y + tb * g.direction.y;
    if (std::min(ya, yb) <= cell_hi_[cell] && std::max(ya, yb) >= cell_lo_[cell]) {
      // A small margin lets hits on a cell's border count in either neighbour.
      const double margin = 1e-9 * (std::fabs(tb) + 1);
      LocalHit hits[2];
      const int n = cell_hits(g, i, k, std::max(t_min, ta - margin), std::min(t_max, tb + margin), hits);
      for (int j = 0; j < n; ++j)
        if (!sink(hits[j])) return;
    }
    if (tb >= t1) return;
    if (next_x < next_z) {
      i += step_i;
      if (i < 0 || i >= cells_w) return;
      next_x += dx;
    } else {
      k += step_k;
      if (k < 0 || k >= cells_d) return;
      next_z += dz;
    }
    ta = tb;
  }
}

bool HeightField::intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const {
  bool any = false;
  walk(ray, t_min, t_max, [&](const LocalHit& h) {
    hit = h;
    any = true;
    return false;
  });
  return any;
}

void HeightField::all_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const {
  double last = -math::kInfinity;
  walk(ray, t_min, t_max, [&](const LocalHit& h) {
    if (h.t > last) hits.push_back(h), last = h.t;  // a hit on a cell border is seen from both cells
    return true;
  });
}

double HeightField::height(double x, double z) const {
  const double gx = std::clamp(x, 0.0, 1.0) * (grid_.width - 1),
               gz = std::clamp(z, 0.0, 1.0) * (grid_.depth - 1);
  const int i = std::min(static_cast<int>(gx), grid_.width - 2),
            k = std::min(static_cast<int>(gz), grid_.depth - 2);
  const double u = gx - i, v = gz - k;
  // Interpolate on the triangle of the cell that holds (u, v); the split runs from (1, 0) to (0, 1).
  if (u + v <= 1) return h(i, k) + u * (h(i + 1, k) - h(i, k)) + v * (h(i, k + 1) - h(i, k));
  return h(i + 1, k + 1) + (1 - u) * (h(i, k + 1) - h(i + 1, k + 1)) +
         (1 - v) * (h(i + 1, k) - h(i + 1, k + 1));
}

bool HeightField::inside(const Vec3& p) const {
  if (p.x < 0 || p.x > 1 || p.z < 0 || p.z > 1 || p.y < std::min(0.0f, y_lo_)) return false;
  return p.y < height(p.x, p.z);
}

}  // namespace snell::geometry
