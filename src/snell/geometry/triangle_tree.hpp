#pragma once
// A WideBvh over triangles only, its leaves packed as TriangleBlocks: the mesh shape's structure. The walk
// hands on the triangles the single-precision filter keeps (triangle_block.hpp), nearest leaves first; the
// owner tests them in double precision, which alone decides hits.
#include <array>
#include <bit>
#include <span>
#include <type_traits>
#include <vector>

#include "snell/geometry/triangle_block.hpp"
#include "snell/geometry/wide_bvh.hpp"

namespace snell::geometry {

class TriangleTree {
 public:
  /// Triangle i has the vertices vertices[faces[i][k]]; its id in visits is i.
  TriangleTree(std::span<const math::Vec3> vertices, std::span<const std::array<int, 3>> faces);

  /// Includes the leaf order (in bvh_.bytes()), through which block b's lane l names face
  /// order()[b.first + l].
  size_t bytes() const { return bvh_.bytes() + blocks_.capacity() * sizeof(TriangleBlock); }
  size_t node_count() const { return bvh_.node_count(); }

  /// Calls visit(triangle, t_max) for each triangle that may be hit within [t_min, t_max]; `visit` may
  /// lower t_max, and a `visit` that returns bool ends the walk by returning true (walk then returns true).
  /// With kOrdered false the leaves come in no particular order (for queries that take any hit:
  /// WideBvh::walk). With kClearEnds (a query that only asks whether the ray crosses a triangle) a lane the
  /// filter calls a clear hit ends the walk unvisited, sparing the owner's test and its reads of the face and
  /// its vertices. L lanes per instruction (math/float_lanes.hpp).
  template <int L, bool kOrdered = true, bool kClearEnds = false, class Visit>
  SNELL_LANES_INLINE bool walk(const math::Ray& ray, double t_min, double t_max, Visit&& visit) const {
    bool ended = false;
    const TriangleRay::Lanes<L> triangle_ray{TriangleRay(ray)};
    const float low = float_below(t_min);
    FloatAboveOnChange high(t_max);
    const bool uniform_errors = scales_.finite();
    const auto errors = triangle_ray.errors(scales_.magnitude, scales_.longest_edge);
    typename TriangleRay::Lanes<L>::WindowOnChange window(low, t_max, errors);
    const auto leaf = [&](uint32_t block, uint32_t, double& t) __attribute__((always_inline)) {
      const TriangleBlock& b = blocks_[block];
      float entry[TriangleBlock::kSize];
      const unsigned lanes = (1u << b.count) - 1;
      unsigned m, clear = 0;
      if constexpr (kClearEnds) {
        m = uniform_errors ? triangle_ray.candidates_among(b, lanes, window(t), entry, errors, clear)
                           : triangle_ray.candidates_among(b, lanes, low, high(t), entry, clear);
      } else {
        m = uniform_errors ? triangle_ray.candidates_among(b, lanes, window(t), entry, errors)
                           : triangle_ray.candidates_among(b, lanes, low, high(t), entry);
      }
      for (; m != 0; m &= m - 1) {
        const int lane = std::countr_zero(m);
        // Lanes in order, so that a clear lane ends the walk only after the lanes before it were tested.
        if (kClearEnds && (clear >> lane & 1u)) return ended = true;
        if (entry[lane] > t) continue;
        const uint32_t face = bvh_.order()[b.first + lane];
        if constexpr (std::is_same_v<decltype(visit(face, t)), bool>) {
          if (visit(face, t)) return ended = true;
        } else {
          visit(face, t);
        }
      }
      return false;
    };
    const auto prefetch = [&](uint32_t block) __attribute__((always_inline)) {
      prefetch_lines(&blocks_[block], sizeof(TriangleBlock));
    };
    bvh_.walk<L, kOrdered>(ray, t_min, t_max, leaf, prefetch);
    return ended;
  }

 private:
  WideBvh bvh_;
  std::vector<TriangleBlock> blocks_;
  /// The blocks' largest error scales (the filter's error terms once per walk where they are finite).
  TriangleScales scales_;
};

}  // namespace snell::geometry
