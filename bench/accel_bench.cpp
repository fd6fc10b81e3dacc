// Rays per second of each accelerator on a random sphere scene, for camera-like coherent rays (a pinhole
// grid from one eye point) and incoherent ones (random origins and directions, like diffuse bounces).
// Run: build/bench/snell_bench --benchmark_filter=Accel
#include <benchmark/benchmark.h>

#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "snell/accel/accelerator.hpp"
#include "snell/geometry/sphere.hpp"
#include "snell/math/pcg32.hpp"

namespace {

using snell::math::Pcg32;
using snell::math::Ray;
using snell::math::Vec3;

constexpr double kSceneHalfSize = 10;
constexpr int kRaysPerBatch = 4096;

double uniform(Pcg32& rng, double lo, double hi) {
  return lo + (hi - lo) * rng.next_double();
}

/// `count` spheres spread in a cube, radii chosen so the scene stays moderately dense at any count.
const snell::scene::Scene& sphere_scene(int count) {
  static std::map<int, snell::scene::Scene> cache;
  auto [it, inserted] = cache.try_emplace(count);
  if (!inserted) return it->second;
  Pcg32 rng(static_cast<uint64_t>(count));
  const double r_max = 2 * kSceneHalfSize / std::cbrt(static_cast<double>(count));
  for (int i = 0; i < count; ++i) {
    const Vec3 c(uniform(rng, -kSceneHalfSize, kSceneHalfSize), uniform(rng, -kSceneHalfSize, kSceneHalfSize),
                 uniform(rng, -kSceneHalfSize, kSceneHalfSize));
    auto o = std::make_shared<snell::scene::Object>();
    o->shape = std::make_shared<snell::geometry::Sphere>(c, uniform(rng, 0.1, 0.5) * r_max);
    it->second.objects.push_back(std::move(o));
  }
  return it->second;
}

/// A 64x64 pinhole grid from in front of the scene, row by row as a tile renderer would trace them.
std::vector<Ray> coherent_rays() {
  std::vector<Ray> rays;
  const Vec3 eye(0, 0, -3 * kSceneHalfSize);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) rays.push_back({eye, normalize(Vec3((x - 31.5) / 96, (y - 31.5) / 96, 1))});
  return rays;
}

std::vector<Ray> incoherent_rays() {
  std::vector<Ray> rays;
  Pcg32 rng(7);
  while (rays.size() < kRaysPerBatch) {
    const Vec3 d(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1));
    if (length_squared(d) > 1 || length_squared(d) < 1e-6) continue;
    const Vec3 o(uniform(rng, -kSceneHalfSize, kSceneHalfSize), uniform(rng, -kSceneHalfSize, kSceneHalfSize),
                 uniform(rng, -kSceneHalfSize, kSceneHalfSize));
    rays.push_back({o, normalize(d)});
  }
  return rays;
}

void trace(benchmark::State& state, const char* kind, const std::vector<Ray>& rays) {
  const auto accel = snell::accel::make_accelerator(kind, sphere_scene(static_cast<int>(state.range(0))));
  int64_t hits = 0;
  for (auto _ : state) {
    for (const Ray& r : rays) {
      snell::scene::SurfaceHit hit;
      hits += accel->intersect(r, 1e-6, std::numeric_limits<double>::infinity(),
                               snell::scene::RayKind::camera, hit);
    }
  }
  benchmark::DoNotOptimize(hits);
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(rays.size()));
  state.counters["hit_fraction"] =
      static_cast<double>(hits) / static_cast<double>(state.iterations() * static_cast<int64_t>(rays.size()));
}

void BM_AccelCoherent(benchmark::State& state, const char* kind) {
  static const std::vector<Ray> rays = coherent_rays();
  trace(state, kind, rays);
}

void BM_AccelIncoherent(benchmark::State& state, const char* kind) {
  static const std::vector<Ray> rays = incoherent_rays();
  trace(state, kind, rays);
}

void BM_AccelBuild(benchmark::State& state) {
  const auto& scene = sphere_scene(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(snell::accel::make_accelerator("embree", scene));
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

}  // namespace

BENCHMARK_CAPTURE(BM_AccelCoherent, embree, "embree")->RangeMultiplier(10)->Range(100, 100000);
BENCHMARK_CAPTURE(BM_AccelCoherent, none, "none")->RangeMultiplier(10)->Range(100, 10000);
BENCHMARK_CAPTURE(BM_AccelIncoherent, embree, "embree")->RangeMultiplier(10)->Range(100, 100000);
BENCHMARK_CAPTURE(BM_AccelIncoherent, none, "none")->RangeMultiplier(10)->Range(100, 10000);
BENCHMARK(BM_AccelBuild)->RangeMultiplier(10)->Range(1000, 100000)->Unit(benchmark::kMillisecond);
