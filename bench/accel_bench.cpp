// Rays per second of each accelerator on random sphere scenes. Two ray sets bracket what a render sees:
// coherent primary-like rays (a pinhole camera's grid) and incoherent rays (random origins and directions,
// like diffuse bounces). Run: build/bench/snell_bench --benchmark_filter='random/10000'
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <vector>

#include "snell/accel/accelerator.hpp"
#include "snell/accel/object_test_counter.hpp"
#include "snell/accel/query_cost.hpp"
#include "snell/geometry/sphere.hpp"
#include "snell/math/pcg32.hpp"

namespace {

using namespace snell;
using math::Vec3;

double uniform(math::Pcg32& rng, double lo, double hi) {
  return lo + (hi - lo) * rng.next_double();
}

/// `count` spheres in a 20-unit cube, radii shrinking with count so the cube stays about equally full.
scene::Scene sphere_scene(int count) {
  math::Pcg32 rng(42);
  scene::Scene s;
  const double radius = 4.0 / std::cbrt(static_cast<double>(count));
  for (int i = 0; i < count; ++i) {
    auto o = std::make_shared<scene::Object>();
    const Vec3 c{uniform(rng, -10, 10), uniform(rng, -10, 10), uniform(rng, -10, 10)};
    o->shape = std::make_shared<geometry::Sphere>(c, radius * uniform(rng, 0.5, 1.0));
    s.objects.push_back(std::move(o));
  }
  return s;
}

std::vector<math::Ray> primary_rays(int n) {
  std::vector<math::Ray> rays;
  const int side = static_cast<int>(std::sqrt(n));
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x) {
      const Vec3 dir{(x + 0.5) / side - 0.5, (y + 0.5) / side - 0.5, 1};
      rays.push_back({{0, 0, -30}, normalize(dir), 0});
    }
  return rays;
}

std::vector<math::Ray> random_rays(int n) {
  math::Pcg32 rng(7);
  std::vector<math::Ray> rays;
  for (int i = 0; i < n; ++i) {
    const Vec3 o{uniform(rng, -10, 10), uniform(rng, -10, 10), uniform(rng, -10, 10)};
    const Vec3 d{uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)};
    rays.push_back({o, normalize(d), 0});
  }
  return rays;
}

void run(benchmark::State& state, const char* kind, bool coherent) {
  const scene::Scene s = sphere_scene(static_cast<int>(state.range(0)));
  const auto accel = accel::make_accelerator(kind, s);
  const std::vector<math::Ray> rays = coherent ? primary_rays(1 << 14) : random_rays(1 << 14);
  size_t hits = 0;
  for (auto _ : state) {
    for (const math::Ray& ray : rays) {
      scene::SurfaceHit hit;
      hits += accel->intersect(ray, 1e-6, math::kInfinity, scene::RayKind::camera, hit);
    }
  }
  benchmark::DoNotOptimize(hits);
  // Work per ray, from one more pass with the counter on (kept out of the timed loop: it costs an atomic).
  accel::ObjectTestCounter::reset();
  accel::ObjectTestCounter::enabled = true;
  accel::QueryCost cost;
  accel::t_query_cost = &cost;
  for (const math::Ray& ray : rays) {
    scene::SurfaceHit hit;
    accel->intersect(ray, 1e-6, math::kInfinity, scene::RayKind::camera, hit);
  }
  accel::t_query_cost = nullptr;
  accel::ObjectTestCounter::enabled = false;
  state.counters["nodes/ray"] = static_cast<double>(cost.nodes) / static_cast<double>(rays.size());
  state.counters["node_KiB"] = static_cast<double>(accel->stats().memory_bytes) / 1024.0;
  state.counters["tests/ray"] =
      static_cast<double>(accel::ObjectTestCounter::total()) / static_cast<double>(rays.size());
  state.counters["rays/s"] =
      benchmark::Counter(static_cast<double>(state.iterations() * rays.size()), benchmark::Counter::kIsRate);
  state.counters["build_ms"] = accel->stats().build_seconds * 1e3;
}

// Embree, the own structures and brute force on the same scenes and rays (1 thread). Brute force is
// O(objects) per ray: it stops at 1000 objects before it takes minutes.
BENCHMARK_CAPTURE(run, embree_primary, "embree", true)->RangeMultiplier(10)->Range(10, 100000);
BENCHMARK_CAPTURE(run, embree_random, "embree", false)->RangeMultiplier(10)->Range(10, 100000);
BENCHMARK_CAPTURE(run, bvh_primary, "bvh", true)->RangeMultiplier(10)->Range(10, 100000);
BENCHMARK_CAPTURE(run, bvh_random, "bvh", false)->RangeMultiplier(10)->Range(10, 100000);
BENCHMARK_CAPTURE(run, octree_primary, "octree", true)->RangeMultiplier(10)->Range(10, 100000);
BENCHMARK_CAPTURE(run, octree_random, "octree", false)->RangeMultiplier(10)->Range(10, 100000);
BENCHMARK_CAPTURE(run, grid_primary, "grid", true)->RangeMultiplier(10)->Range(10, 100000);
BENCHMARK_CAPTURE(run, grid_random, "grid", false)->RangeMultiplier(10)->Range(10, 100000);
BENCHMARK_CAPTURE(run, brute_primary, "none", true)->RangeMultiplier(10)->Range(10, 1000);
BENCHMARK_CAPTURE(run, brute_random, "none", false)->RangeMultiplier(10)->Range(10, 1000);

}  // namespace
