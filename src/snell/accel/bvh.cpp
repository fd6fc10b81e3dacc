#include "snell/accel/bvh.hpp"

#include <bit>
#include <chrono>

#include "snell/accel/indexed_objects.hpp"

namespace snell::accel {

namespace {

// SAH costs relative to one node visit: an object test (a transformed quadric, a CSG walk) costs several;
// a block of up to eight triangles, filtered at once, about two.
constexpr double kObjectCost = 4.0;
constexpr double kTriangleBlockCost = 2.0;
/// Spatial splits may put each object in two leaves on average (docs/benchmark.md: long triangles).
constexpr double kReferenceBudget = 2;

/// A triangle's corner in world space (its transform applied in double).
math::Vec3 world_point(const PlainTriangle& t, const math::Vec3& p) {
  return t.transform ? t.transform->point(p) : p;
}

/// Bits 8k .. 8k + 7 of a block's tag hold the lanes ray kind k sees: the shift for a kind (taken once per
/// query, not per block).
int visible_shift(scene::RayKind kind) {
  return 8 * static_cast<int>(kind);
}

}  // namespace

Bvh::Bvh(const scene::Scene& scene) {
  const auto start = std::chrono::steady_clock::now();
  const IndexedObjects indexed(scene);
  unbounded_ = indexed.unbounded;
  const std::vector<PlainTriangle> plain = plain_triangles(indexed.bounded);
  std::vector<uint8_t> kinds;
  kinds.reserve(plain.size());
  for (const PlainTriangle& t : plain) kinds.push_back(t.shape ? 1 : 0);
  std::vector<std::array<math::Vec3, 3>> corners(plain.size());
  for (size_t i = 0; i < plain.size(); ++i)
    if (plain[i].shape)
      for (int k = 0; k < 3; ++k) corners[i][k] = world_point(plain[i], plain[i].vertices[k]);
  geometry::WideBvh::Input input;
  input.boxes = indexed.boxes;
  input.kinds = kinds;
  input.triangles = corners;
  input.reference_budget = kReferenceBudget;
  input.cost = {kObjectCost, kTriangleBlockCost};
  input.group = {1, geometry::TriangleBlock::kSize};
  input.max_leaf = geometry::TriangleBlock::kSize;
  tree_ = geometry::WideBvh(input);
  for (uint32_t i : tree_.order()) objects_.push_back(indexed.bounded[i]);
  // Triangle leaves become blocks, their triangles in world space (a transform applied in double, then
  // rounded: the filter's margin covers both).
  tree_.relabel_leaves([&](uint32_t first, uint32_t count) {
    const uint32_t primitive = tree_.order()[first];
    if (!plain[primitive].shape) return first;
    geometry::TriangleBlock& block = blocks_.emplace_back();
    block.first = static_cast<uint32_t>(triangles_.size());
    for (uint32_t i = first; i < first + count; ++i) {
      const PlainTriangle& t = plain[tree_.order()[i]];
      const std::array<math::Vec3, 3>& v = t.vertices;
      const int lane = static_cast<int>(block.count);
      block.add(world_point(t, v[0]), world_point(t, v[1]), world_point(t, v[2]));
      for (scene::RayKind kind : {scene::RayKind::camera, scene::RayKind::reflection,
                                  scene::RayKind::refraction, scene::RayKind::shadow})
        if (t.object->visible_to(kind)) block.tag |= 1u << (8 * static_cast<int>(kind) + lane);
      // Without a transform the double test runs on these vertices: a clear hit of the filter stands.
      if (!t.transform) block.decisive |= static_cast<uint8_t>(1u << lane);
      triangles_.push_back(t);
      triangle_objects_.push_back(t.object);
    }
    return static_cast<uint32_t>(blocks_.size() - 1) | kTriangleLeaf;
  });
  blocks_.shrink_to_fit();
  for (const geometry::TriangleBlock& block : blocks_) scales_.include(block);
  stats_ = structure_stats(scene.objects.size(), unbounded_.size(), tree_.node_count(),
                           tree_.bytes() + objects_.size() * sizeof(objects_[0]) +
                               triangles_.size() * sizeof(PlainTriangle) +
                               blocks_.size() * sizeof(geometry::TriangleBlock),
                           start);
}

template <int L, bool kAnyHit>
SNELL_LANES_INLINE void Bvh::walk(NearestHit& nearest) const {
  const math::Ray& ray = nearest.ray();
  const geometry::TriangleRay::Lanes<L> triangle_ray{geometry::TriangleRay(ray)};
  const float t_min = geometry::float_below(nearest.t_min());
  geometry::FloatAboveOnChange float_t_max(nearest.t_max());
  const int shift = visible_shift(nearest.kind());
  // Error terms for every block at once where the scales allow (part of the filter's scalar work per block;
  // random rays through 100k triangles: 0.8% fewer instructions), else each block's own. Chosen here, not
  // inside the filter: a flag tested per block there cost more than it saved.
  const bool uniform_errors = scales_.finite();
  const auto errors = triangle_ray.errors(scales_.magnitude, scales_.longest_edge);
  typename geometry::TriangleRay::Lanes<L>::WindowOnChange window(t_min, nearest.t_max(), errors);
  const auto leaf = [&](uint32_t label, uint32_t count, double& t_max) __attribute__((always_inline)) {
    bool hit = false;
    if (label & kTriangleLeaf) {
      const geometry::TriangleBlock& block = blocks_[label & ~kTriangleLeaf];
      const uint32_t visible = (block.tag >> shift) & 0xffu;
      ObjectTestCounter::count(static_cast<uint64_t>(std::popcount(visible)));
      if (t_query_cost)
        for (uint32_t m = visible; m != 0; m &= m - 1)
          count_object_test(*triangles_[block.first + std::countr_zero(m)].object);
      float entry[geometry::TriangleBlock::kSize];
      unsigned clear = 0;
      uint32_t m;
      if constexpr (kAnyHit) {
        m = uniform_errors
                ? triangle_ray.candidates_among(block, visible, window(t_max), entry, errors, clear)
                : triangle_ray.candidates_among(block, visible, t_min, float_t_max(t_max), entry, clear);
      } else {
        m = uniform_errors ? triangle_ray.candidates_among(block, visible, window(t_max), entry, errors)
                           : triangle_ray.candidates_among(block, visible, t_min, float_t_max(t_max), entry);
      }
      for (; m != 0; m &= m - 1) {
        const int lane = std::countr_zero(m);
        // A clear hit ends the walk on its object alone, from the compact array: the record's read (a miss
        // in a large scene) and the double test are for the lanes the filter cannot settle. Lanes in order,
        // as the double test would take them.
        if (kAnyHit && (clear >> lane & 1u)) {
          nearest.blocked_by(*triangle_objects_[block.first + lane]);
          hit = true;
          break;
        }
        if (entry[lane] > nearest.t_max()) continue;
        if (nearest.test_triangle(triangles_[block.first + lane])) {
          hit = true;
          if (kAnyHit) break;
        }
      }
    } else {
      for (uint32_t i = label; i < label + count; ++i)
        if (kAnyHit ? nearest.test_blocking(*objects_[i]) : nearest.test_general(*objects_[i])) {
          hit = true;
          if (kAnyHit) break;
        }
    }
    t_max = nearest.t_max();
    return hit && kAnyHit;
  };
  NodeTally tally;
  const auto prefetch = [&](uint32_t label) __attribute__((always_inline)) {
    if (label & kTriangleLeaf)
      geometry::prefetch_lines(&blocks_[label & ~kTriangleLeaf], sizeof(geometry::TriangleBlock));
  };
  // An occlusion query takes any hit: its walk needs no order.
  tally.add(tree_.walk<L, !kAnyHit>(ray, nearest.t_min(), nearest.t_max(), leaf, prefetch));
}

bool Bvh::intersect(const math::Ray& ray, double t_min, double t_max, scene::RayKind kind,
                    scene::SurfaceHit& hit) const {
  NearestHit nearest(ray, t_min, t_max, kind, hit);
  for (const scene::Object* o : unbounded_) nearest.test_general(*o);
  math::lanes::with_lanes([&]<int L>() __attribute__((always_inline)) { walk<L, false>(nearest); });
  return nearest.finish();
}

const scene::Object* Bvh::occluder(const math::Ray& ray, double t_min, double t_max,
                                   scene::RayKind kind) const {
  scene::SurfaceHit scratch;
  NearestHit nearest(ray, t_min, t_max, kind, scratch);
  for (const scene::Object* o : unbounded_)
    if (nearest.test_blocking(*o)) return o;
  math::lanes::with_lanes([&]<int L>() __attribute__((always_inline)) { walk<L, true>(nearest); });
  return nearest.object();
}

}  // namespace snell::accel
