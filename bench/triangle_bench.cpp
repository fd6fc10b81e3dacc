// Rays per second on the same triangles: Embree called directly (float triangles, rtcIntersect1 and
// rtcOccluded1, nothing of snell in between) against each of snell's accelerators, which see the
// triangles as scene objects and intersect them in double precision, and against snell's mesh shape
// (the triangles as one `mesh`, under its own BVH). Three ray sets: coherent primary rays (a pinhole
// camera's grid), incoherent rays (random origins and directions, like diffuse bounces) and shadow rays
// (occlusion queries from points on the triangles towards a light, most of them blocked part way).
// Run: build/bench/snell_bench --benchmark_filter='triangles|slivers' (SNELL_BENCH_TRIANGLES=n: soups of n
// triangles).
#include <benchmark/benchmark.h>
#include <embree3/rtcore.h>

#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "snell/accel/accelerator.hpp"
#include "snell/accel/query_cost.hpp"
#include "snell/geometry/mesh.hpp"
#include "snell/geometry/triangle.hpp"
#include "snell/math/pcg32.hpp"

namespace {

using namespace snell;
using math::Vec3;

/// Triangles in each soup: 100,000, or SNELL_BENCH_TRIANGLES (1 to 10,000,000) for the effect of the
/// soup's size (the caches) on the ratios.
int soup_size() {
  constexpr int kDefault = 100000, kLargest = 10000000;
  const char* text = std::getenv("SNELL_BENCH_TRIANGLES");
  if (text == nullptr) return kDefault;
  char* end = nullptr;
  const long n = std::strtol(text, &end, 10);
  if (end == text || *end != '\0' || n < 1 || n > kLargest) {
    std::fprintf(stderr, "snell_bench: SNELL_BENCH_TRIANGLES must be a count from 1 to %d, not '%s'\n",
                 kLargest, text);
    std::exit(2);
  }
  return static_cast<int>(n);
}
constexpr int kRays = 1 << 14;

double uniform(math::Pcg32& rng, double lo, double hi) {
  return lo + (hi - lo) * rng.next_double();
}

/// A soup of `count` small triangles in a 20-unit cube, each a random triangle about as wide as the mean
/// spacing of their centres: boxes overlap as in a crumpled mesh, and most rays stop within the cube.
/// `stretch` > 1 makes slivers: two corners pulled apart along a random axis to `stretch` times that width
/// each way, long triangles whose boxes overlap far more than their surfaces (as in tessellated CAD
/// models), where spatial splits pay.
std::vector<std::array<Vec3, 3>> triangle_soup(int count, double stretch) {
  math::Pcg32 rng(42);
  const double size = 0.5 * 20 / std::cbrt(static_cast<double>(count));
  std::vector<std::array<Vec3, 3>> soup;
  for (int i = 0; i < count; ++i) {
    const Vec3 c{uniform(rng, -10, 10), uniform(rng, -10, 10), uniform(rng, -10, 10)};
    std::array<Vec3, 3> t;
    for (Vec3& v : t) v = c + Vec3{uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)} * size;
    if (stretch > 1) {
      const auto axis = static_cast<int>(rng.next_uint() % 3);
      t[0][axis] = c[axis] - stretch * size;
      t[1][axis] = c[axis] + stretch * size;
    }
    soup.push_back(t);
  }
  return soup;
}

struct Query {
  math::Ray ray;
  double t_max;
};

std::vector<Query> queries(const std::vector<std::array<Vec3, 3>>& soup, int kind) {
  math::Pcg32 rng(7);
  std::vector<Query> out;
  const int side = static_cast<int>(std::sqrt(kRays));
  for (int i = 0; i < kRays; ++i) {
    if (kind == 0) {  // primary: a camera grid
      const Vec3 dir{((i % side) + 0.5) / side - 0.5, ((i / side) + 0.5) / side - 0.5, 1};
      out.push_back({{{0, 0, -30}, normalize(dir), 0}, math::kInfinity});
    } else if (kind == 1) {  // incoherent
      const Vec3 o{uniform(rng, -10, 10), uniform(rng, -10, 10), uniform(rng, -10, 10)};
      const Vec3 d{uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)};
      out.push_back({{o, normalize(d), 0}, math::kInfinity});
    } else {  // shadow: from a triangle's centre towards a light outside the cube
      const auto& t = soup[rng.next_uint() % soup.size()];
      const Vec3 p = (t[0] + t[1] + t[2]) / 3.0;
      const Vec3 light{30, 40, -20};
      const Vec3 d = light - p;
      out.push_back({{p, normalize(d), 0}, length(d)});
    }
  }
  return out;
}

const char* kKindNames[] = {"primary", "random", "shadow"};

/// Embree on its own: a float triangle geometry, high-quality build, one rtcIntersect1 / rtcOccluded1 per
/// ray with the same origin, direction and window as snell's queries get.
/// A byte count in MiB, for the benchmarks' memory counters.
double mebibytes(size_t bytes) {
  return static_cast<double>(bytes) / (1 << 20);
}

class RawEmbree {
 public:
  explicit RawEmbree(const std::vector<std::array<Vec3, 3>>& soup) {
    device_ = rtcNewDevice(nullptr);
    // Embree reports each allocation and release, from its build threads at once (hence atomic): the
    // running sum is the memory its scene holds.
    rtcSetDeviceMemoryMonitorFunction(
        device_,
        [](void* user, ssize_t bytes, bool) {
          *static_cast<std::atomic<ssize_t>*>(user) += bytes;
          return true;
        },
        &bytes_);
    scene_ = rtcNewScene(device_);
    rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
    RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                          3 * sizeof(float), 3 * soup.size()));
    auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                               3 * sizeof(unsigned), soup.size()));
    for (size_t i = 0; i < soup.size(); ++i)
      for (int k = 0; k < 3; ++k) {
        for (int a = 0; a < 3; ++a) v[9 * i + 3 * k + a] = static_cast<float>(soup[i][k][a]);
        idx[3 * i + k] = static_cast<unsigned>(3 * i + k);
      }
    rtcCommitGeometry(g);
    rtcAttachGeometry(scene_, g);
    rtcReleaseGeometry(g);
    rtcCommitScene(scene_);
  }
  ~RawEmbree() {
    rtcReleaseScene(scene_);
    rtcReleaseDevice(device_);
  }
  /// Bytes Embree holds for the scene: its tree, leaves and the vertex and index buffers.
  size_t bytes() const { return static_cast<size_t>(bytes_.load()); }
  RawEmbree(const RawEmbree&) = delete;
  RawEmbree& operator=(const RawEmbree&) = delete;

  bool query(const Query& q, bool occlusion) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh;
    RTCRay& r = rh.ray;
    r.org_x = static_cast<float>(q.ray.origin.x);
    r.org_y = static_cast<float>(q.ray.origin.y);
    r.org_z = static_cast<float>(q.ray.origin.z);
    r.dir_x = static_cast<float>(q.ray.direction.x);
    r.dir_y = static_cast<float>(q.ray.direction.y);
    r.dir_z = static_cast<float>(q.ray.direction.z);
    r.tnear = 1e-4f;
    r.tfar = std::isinf(q.t_max) ? std::numeric_limits<float>::infinity() : static_cast<float>(q.t_max);
    r.time = 0;
    r.mask = ~0u;
    r.id = 0;
    r.flags = 0;
    if (occlusion) {
      rtcOccluded1(scene_, &context, &r);
      return r.tfar < 0;
    }
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene_, &context, &rh);
    return rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
  }

 private:
  RTCDevice device_;
  RTCScene scene_;
  std::atomic<ssize_t> bytes_ = 0;
};

/// The two soups: 0 small triangles, 1 slivers.
const std::vector<std::array<Vec3, 3>>& soup(int which = 0) {
  static const std::vector<std::array<Vec3, 3>> small = triangle_soup(soup_size(), 1);
  static const std::vector<std::array<Vec3, 3>> slivers = triangle_soup(soup_size(), 4);
  return which == 0 ? small : slivers;
}

void count_rays(benchmark::State& state, size_t hits, size_t rays) {
  benchmark::DoNotOptimize(hits);
  state.counters["rays/s"] =
      benchmark::Counter(static_cast<double>(state.iterations() * rays), benchmark::Counter::kIsRate);
  state.counters["hit_fraction"] = static_cast<double>(hits) / static_cast<double>(state.iterations() * rays);
}

void raw_embree(benchmark::State& state, int kind, int which) {
  const RawEmbree embree(soup(which));
  const std::vector<Query> qs = queries(soup(which), kind);
  size_t hits = 0;
  for (auto _ : state)
    for (const Query& q : qs) hits += embree.query(q, kind == 2);
  count_rays(state, hits, qs.size());
  state.counters["MiB"] = mebibytes(embree.bytes());
}

/// The triangles as separate scene objects (one `triangle` each), or as one `mesh` object.
scene::Scene triangle_scene(bool as_mesh, int which) {
  scene::Scene s;
  if (as_mesh) {
    geometry::MeshData data;
    for (const auto& t : soup(which)) {
      const int base = static_cast<int>(data.vertices.size());
      for (const Vec3& v : t) data.vertices.push_back(v);
      data.faces.push_back({base, base + 1, base + 2});
    }
    auto o = std::make_shared<scene::Object>();
    o->shape = std::make_shared<geometry::Mesh>(std::move(data));
    s.objects.push_back(std::move(o));
    return s;
  }
  for (const auto& t : soup(which)) {
    auto o = std::make_shared<scene::Object>();
    o->shape = std::make_shared<geometry::Triangle>(t[0], t[1], t[2]);
    s.objects.push_back(std::move(o));
  }
  return s;
}

/// The query of ray set `kind` through a snell accelerator: an occlusion query for shadow rays, else the
/// nearest hit.
bool snell_query(const accel::Accelerator& accel, const Query& q, int kind) {
  if (kind == 2) return accel.occluder(q.ray, 1e-4, q.t_max, scene::RayKind::shadow) != nullptr;
  scene::SurfaceHit hit;
  return accel.intersect(q.ray, 1e-4, q.t_max, scene::RayKind::camera, hit);
}

void snell_accel(benchmark::State& state, const char* accel_kind, int kind, bool as_mesh, int which) {
  const scene::Scene s = triangle_scene(as_mesh, which);
  const auto accel = accel::make_accelerator(accel_kind, s);
  const std::vector<Query> qs = queries(soup(which), kind);
  // One query before timing: the mesh shape builds its tree on the first one.
  scene::SurfaceHit warm_up;
  accel->intersect(qs[0].ray, 1e-4, qs[0].t_max, scene::RayKind::camera, warm_up);
  const auto hit_by = [&](const Query& q) { return snell_query(*accel, q, kind); };
  // One untimed pass with the cost tally on: node visits and primitive tests per ray, the structure's
  // share of the figures (accel/query_cost.hpp).
  accel::QueryCost cost;
  accel::t_query_cost = &cost;
  for (const Query& q : qs) hit_by(q);
  accel::t_query_cost = nullptr;
  size_t hits = 0;
  for (auto _ : state)
    for (const Query& q : qs) hits += hit_by(q);
  count_rays(state, hits, qs.size());
  state.counters["nodes/ray"] = static_cast<double>(cost.nodes) / static_cast<double>(qs.size());
  state.counters["tests/ray"] = static_cast<double>(cost.primitives) / static_cast<double>(qs.size());
  // A mesh's own triangle tree is not in the accelerator's figure: memory is reported for separate objects.
  if (!as_mesh) state.counters["MiB"] = mebibytes(accel->stats().memory_bytes);
}

/// Embree alone and the own BVH timed in turns on the same rays, a whole pass over the ray set each, so that
/// the drift of a shared machine's speed (tens of percent within minutes here) falls on both alike: the
/// counter `bvh/embree` is the ratio of their throughputs, where separate runs of the two scatter by +-10%.
/// Turns of a pass each keep both in their steady state: with turns of 256 or 2048 rays each evicted the
/// other's nodes from the caches and Embree, the faster, lost more (the ratio rose from 0.55 to 0.63-0.66).
void bvh_against_embree(benchmark::State& state, int kind) {
  const RawEmbree embree(soup(0));
  const scene::Scene s = triangle_scene(false, 0);
  const auto bvh = accel::make_accelerator("bvh", s);
  const std::vector<Query> qs = queries(soup(0), kind);
  using Clock = std::chrono::steady_clock;
  Clock::duration embree_time{}, bvh_time{};
  size_t embree_hits = 0, bvh_hits = 0;
  for (auto _ : state) {
    const auto start = Clock::now();
    for (const Query& q : qs) embree_hits += embree.query(q, kind == 2);
    const auto middle = Clock::now();
    for (const Query& q : qs) bvh_hits += snell_query(*bvh, q, kind);
    embree_time += middle - start;
    bvh_time += Clock::now() - middle;
  }
  benchmark::DoNotOptimize(embree_hits + bvh_hits);
  state.counters["bvh/embree"] =
      std::chrono::duration<double>(embree_time).count() / std::chrono::duration<double>(bvh_time).count();
}

void register_all() {
  for (int kind = 0; kind < 3; ++kind) {
    const std::string suffix = kKindNames[kind];
    benchmark::RegisterBenchmark(("triangles/raw_embree_" + suffix).c_str(), raw_embree, kind, 0)
        ->Unit(benchmark::kMillisecond);
    for (const char* a : {"embree", "bvh", "octree", "grid"})
      benchmark::RegisterBenchmark(("triangles/" + std::string(a) + "_" + suffix).c_str(), snell_accel, a,
                                   kind, false, 0)
          ->Unit(benchmark::kMillisecond);
    // One mesh object: Embree walks it as native float triangles (each hit redone in double); the own
    // accelerators hand it to the mesh's own BVH.
    for (const char* a : {"embree", "bvh"})
      benchmark::RegisterBenchmark(("triangles/" + std::string(a) + "_mesh_" + suffix).c_str(), snell_accel,
                                   a, kind, true, 0)
          ->Unit(benchmark::kMillisecond);
  }
  for (int kind = 0; kind < 3; ++kind)
    benchmark::RegisterBenchmark(("triangles/bvh_against_embree_" + std::string(kKindNames[kind])).c_str(),
                                 bvh_against_embree, kind)
        ->Unit(benchmark::kMillisecond);
  // Incoherent rays through the slivers: Embree alone (its high-quality build makes spatial splits) and
  // the own BVH, which makes them too (tests/geometry/wide_bvh_test.cpp prints the visits without).
  benchmark::RegisterBenchmark("slivers/raw_embree_random", raw_embree, 1, 1)->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("slivers/bvh_random", snell_accel, "bvh", 1, false, 1)
      ->Unit(benchmark::kMillisecond);
}

const bool registered = (register_all(), true);

}  // namespace
