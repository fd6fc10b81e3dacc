#include "snell/render/explain/aov_render.hpp"

#include "snell/geometry/surface_uv.hpp"
#include "snell/render/aa_neighbours.hpp"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <limits>
#include <map>
#include <stdexcept>
#include <unordered_map>

#include "snell/accel/query_cost.hpp"
#include "snell/render/explain/sample_observer.hpp"
#include "snell/render/integrator.hpp"
#include "snell/scene/csg.hpp"

namespace snell::render::explain {

namespace {

using Clock = std::chrono::steady_clock;

/// Each object (CSG children too) mapped to its top-level index, each texture to its number in scene order.
struct SceneIds {
  std::unordered_map<const scene::Object*, int> object;
  std::unordered_map<const material::Texture*, int> material;

  explicit SceneIds(const scene::Scene& scene) {
    for (size_t i = 0; i < scene.objects.size(); ++i) add(*scene.objects[i], static_cast<int>(i));
  }
  void add(const scene::Object& o, int index) {
    object.emplace(&o, index);
    if (o.texture) material.emplace(o.texture.get(), static_cast<int>(material.size()));
    if (o.csg)
      for (const auto& child : o.csg->children()) add(*child, index);
  }
  int object_id(const scene::SurfaceHit& hit) const {
    const auto it = object.find(hit.solid ? hit.solid : hit.object);
    if (it != object.end()) return it->second;
    const auto leaf = object.find(hit.object);
    return leaf == object.end() ? -1 : leaf->second;
  }
  int material_id(const scene::Object& o) const {
    const auto it = material.find(o.texture.get());
    return it == material.end() ? -1 : it->second;
  }
};

/// What one pixel gathered over its samples.
struct PixelRecord {
  math::Color colour{0, 0, 0};
  int samples = 0;
  bool hit = false;
  scene::SurfaceHit first;
  math::Color albedo{0, 0, 0};
  uint64_t nodes = 0, primitives = 0, rays = 0, nanoseconds = 0;
  std::vector<math::Color> bounces;
};

struct ThreadState {
  TraceContext context;
  SampleObserver observer;
  accel::QueryCost cost;
  std::unordered_map<const scene::Object*, uint64_t> per_object;
  explicit ThreadState(int split) : observer(split) {}
};

}  // namespace

const std::vector<std::string_view>& aov_names() {
  static const std::vector<std::string_view> names{"depth",    "normal", "albedo",  "position", "object",
                                                   "material", "uv",     "samples", "cost",     "time"};
  return names;
}

AovRender render_aovs(const scene::Scene& scene, const accel::Accelerator& accelerator,
                      const RenderOptions& options, const std::vector<std::string>& names, int split_depth) {
  for (const std::string& n : names)
    if (std::find(aov_names().begin(), aov_names().end(), n) == aov_names().end())
      throw std::invalid_argument("unknown layer " + n);
  const int w = options.width, h = options.height;
  const auto integrator = make_integrator(options.integrator, scene, accelerator);
  const auto camera = scene::make_camera(scene.camera);
  const SceneIds ids(scene);
  std::vector<PixelRecord> pixels(static_cast<size_t>(w) * h);
  tbb::enumerable_thread_specific<ThreadState> states([&] { return ThreadState(split_depth); });

  // One sample of pixel (x, y), added to its record with what it cost.
  auto trace_sample = [&](int x, int y, int k, ThreadState& s) {
    PixelRecord& p = pixels[static_cast<size_t>(y) * w + x];
    const auto start = Clock::now();
    const uint64_t rays_before = s.context.counters.total();
    s.cost.nodes = s.cost.primitives = 0;
    s.cost.per_object = &s.per_object;
    accel::t_query_cost = &s.cost;
    s.observer.reset();
    s.context.observer = &s.observer;
    const math::Vec2 at = sample_position(options, x, y, k);
    seed_camera_sample(s.context.rng, at.u, at.v, options);
    const auto ray = camera->generate_ray(at.u, at.v, options.time);
    const math::Color c = ray ? integrator->trace_camera_ray(*ray, s.context) : math::Color{0, 0, 0};
    accel::t_query_cost = nullptr;
    p.colour += c;
    ++p.samples;
    if (k == 0 && ray && s.observer.first_hit_found()) {
      p.hit = true;
      p.first = s.observer.first_hit();
      const scene::SurfaceHit& fh = p.first;
      p.albedo = fh.object->texture->pigment_at(fh.point, fh.normal, fh.uv).rgb;
    }
    if (split_depth >= 0) {
      const auto& b = s.observer.bounces();
      if (p.bounces.empty()) p.bounces.assign(b.size(), math::Color{0, 0, 0});
      if (ray)
        for (size_t i = 0; i < b.size(); ++i) p.bounces[i] += b[i];
    }
    p.nodes += s.cost.nodes;
    p.primitives += s.cost.primitives;
    p.rays += s.context.counters.total() - rays_before;
    p.nanoseconds += static_cast<uint64_t>(std::chrono::nanoseconds(Clock::now() - start).count());
  };

  auto rows = [&](auto&& per_pixel) {
    tbb::parallel_for(0, h, [&](int y) {
      ThreadState& s = states.local();
      for (int x = 0; x < w; ++x) per_pixel(x, y, s);
    });
  };
  auto run = [&] {
    rows([&](int x, int y, ThreadState& s) { trace_sample(x, y, 0, s); });
    if (!options.antialias) return;
    // Supersample as the renderer does, tile by tile in POV-Ray's order (aa_neighbours.hpp).
    std::vector<math::Color> first(pixels.size());
    for (size_t i = 0; i < pixels.size(); ++i) first[i] = pixels[i].colour;
    // A first sample of the row above or the column left of the image, seen only for comparison.
    auto outside = [&](int x, int y, ThreadState& s) {
      s.context.observer = nullptr;
      const math::Vec2 at = sample_position(options, x, y, 0);
      seed_camera_sample(s.context.rng, at.u, at.v, options);
      const auto ray = camera->generate_ray(at.u, at.v, options.time);
      return ray ? integrator->trace_camera_ray(*ray, s.context) : math::Color{0, 0, 0};
    };
    const int n = options.aa_depth;
    const std::vector<Tile> tiles = make_tiles(w, h, {0, 0, w, h});
    tbb::parallel_for(size_t{0}, tiles.size(), [&](size_t t) {
      ThreadState& s = states.local();
      std::vector<math::Color> out;
      std::vector<char> refined;
      supersample_block(
          tiles[t].rect, options.aa_threshold, options.aa_compare_exponent,
          [&](int x, int y) {
            return x < 0 || y < 0 ? outside(x, y, s) : first[static_cast<size_t>(y) * w + x];
          },
          [&](int x, int y, const math::Color&) {
            for (int k = 1; k <= n * n; ++k) trace_sample(x, y, k, s);
            const PixelRecord& p = pixels[static_cast<size_t>(y) * w + x];
            return p.colour / std::max(1, p.samples);
          },
          out, refined);
    });
  };
  if (options.threads > 0) {
    tbb::task_arena arena(options.threads);
    arena.execute(run);
  } else {
    run();
  }

  AovRender out;
  out.beauty = io::Image(w, h);
  auto layer = [&](std::string name, std::vector<std::string> channels, bool is_id = false) -> Layer& {
    Layer l{std::move(name), std::move(channels), {}, is_id};
    l.values.assign(pixels.size() * l.channels.size(), 0.0f);
    out.layers.push_back(std::move(l));
    return out.layers.back();
  };
  for (size_t i = 0; i < pixels.size(); ++i) {
    const PixelRecord& p = pixels[i];
    out.beauty.set(static_cast<int>(i % w), static_cast<int>(i / w), p.colour / std::max(1, p.samples));
    out.camera_rays += static_cast<uint64_t>(p.samples);
    out.nodes += p.nodes;
    out.primitives += p.primitives;
    out.rays += p.rays;
  }
  const auto f = [](double v) { return static_cast<float>(v); };
  for (const std::string& name : names) {
    Layer* l = nullptr;
    if (name == "depth") l = &layer(name, {"Z"});
    if (name == "normal") l = &layer(name, {"X", "Y", "Z"});
    if (name == "albedo") l = &layer(name, {"R", "G", "B"});
    if (name == "position") l = &layer(name, {"X", "Y", "Z"});
    if (name == "object") l = &layer(name, {"id"}, true);
    if (name == "material") l = &layer(name, {"id"}, true);
    if (name == "uv") {
      l = &layer(name, {"U", "V"});
      geometry::request_surface_uv();
    }
    if (name == "samples") l = &layer(name, {"count"});
    if (name == "cost") l = &layer(name, {"nodes", "primitives", "rays"});
    if (name == "time") l = &layer(name, {"ns"});
    const size_t nc = l->channels.size();
    for (size_t i = 0; i < pixels.size(); ++i) {
      const PixelRecord& p = pixels[i];
      float* v = &l->values[i * nc];
      const scene::SurfaceHit& s = p.first;
      if (name == "depth") v[0] = p.hit ? f(s.t) : std::numeric_limits<float>::infinity();
      if (name == "normal" && p.hit) v[0] = f(s.normal.x), v[1] = f(s.normal.y), v[2] = f(s.normal.z);
      if (name == "albedo" && p.hit) v[0] = f(p.albedo.r), v[1] = f(p.albedo.g), v[2] = f(p.albedo.b);
      if (name == "position" && p.hit) v[0] = f(s.point.x), v[1] = f(s.point.y), v[2] = f(s.point.z);
      if (name == "object") v[0] = p.hit ? f(ids.object_id(s)) : -1.0f;
      if (name == "material") v[0] = p.hit ? f(ids.material_id(*s.object)) : -1.0f;
      if (name == "uv" && p.hit) v[0] = f(s.uv.u), v[1] = f(s.uv.v);
      if (name == "samples") v[0] = f(p.samples);
      if (name == "cost") v[0] = f(double(p.nodes)), v[1] = f(double(p.primitives)), v[2] = f(double(p.rays));
      if (name == "time") v[0] = f(double(p.nanoseconds));
    }
  }
  if (split_depth >= 0) {
    const std::vector<std::string> bounce = bounce_names(split_depth);
    for (size_t b = 0; b < bounce.size(); ++b) {
      Layer& l = layer(bounce[b], {"R", "G", "B"});
      for (size_t i = 0; i < pixels.size(); ++i) {
        const PixelRecord& p = pixels[i];
        const math::Color c =
            p.bounces.empty() ? math::Color{0, 0, 0} : p.bounces[b] / std::max(1, p.samples);
        l.values[i * 3] = f(c.r), l.values[i * 3 + 1] = f(c.g), l.values[i * 3 + 2] = f(c.b);
      }
    }
  }
  std::unordered_map<const scene::Object*, uint64_t> tests;
  for (const ThreadState& s : states)
    for (const auto& [object, n] : s.per_object) tests[object] += n;
  for (const auto& [object, n] : tests) {
    const auto it = ids.object.find(object);
    out.object_costs.push_back({object, it == ids.object.end() ? -1 : it->second, n});
  }
  std::sort(out.object_costs.begin(), out.object_costs.end(), [](const ObjectCost& a, const ObjectCost& b) {
    return a.tests != b.tests ? a.tests > b.tests : a.index < b.index;
  });
  return out;
}

}  // namespace snell::render::explain
