#include "snell/accel/embree_accelerator.hpp"

#include <embree3/rtcore.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <string>

namespace snell::accel {
namespace {

constexpr float kFloatInf = std::numeric_limits<float>::infinity();

float round_down(double x) {
  return std::nextafter(static_cast<float>(x), -kFloatInf);
}
float round_up(double x) {
  return std::nextafter(static_cast<float>(x), kFloatInf);
}

/// Embree's float traversal sees a rounded copy of each double ray, so boxes are widened by this fraction
/// of the scene's size. The float ray starts inside the scene box (see `intersect`), so its error is a few
/// float ulps (~1.2e-7) of the scene size; 4e-6 leaves a wide margin at a negligible cost in culling.
constexpr double kRelativePad = 4e-6;

struct FloatBox {
  float lo[3];
  float hi[3];
};

/// Per-query state. Embree hands the intersect callback the RTCIntersectContext pointer we passed to
/// rtcIntersect1; putting that context first lets the callback reach the rest (Embree 3 API docs,
/// RTCIntersectContext: "extend the intersection context with additional data").
struct QueryContext {
  RTCIntersectContext rtc;
  const scene::Object* const* objects;
  const math::Ray* ray;
  double t_min;
  /// Current far end: the nearest hit so far, or the caller's t_max.
  double t_max;
  /// Ray parameter of the float ray's origin along the double ray.
  double t_offset;
  scene::RayKind kind;
  scene::SurfaceHit* hit;
  bool found;
};

}  // namespace

struct EmbreeAccelerator::Embree {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::vector<FloatBox> boxes;
  /// Padded world bounds of all bounded objects, in double.
  math::Bounds3 scene_bounds;
  std::mutex error_mutex;
  std::string error;

  ~Embree() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }

  /// Embree reports errors through this callback, from inside its own C API; an exception may not cross
  /// that boundary, so the message is kept and `check` throws it once the API call has returned.
  static void on_error(void* user, RTCError code, const char* message) {
    auto* self = static_cast<Embree*>(user);
    const std::lock_guard lock(self->error_mutex);
    if (self->error.empty())
      self->error =
          "Embree error " + std::to_string(static_cast<int>(code)) + ": " + (message ? message : "");
  }

  void check(const char* what) {
    const std::lock_guard lock(error_mutex);
    if (!error.empty()) throw std::runtime_error(std::string(what) + ": " + error);
  }
};

namespace {

void bounds_callback(const RTCBoundsFunctionArguments* args) {
  const auto& boxes = *static_cast<const std::vector<FloatBox>*>(args->geometryUserPtr);
  const FloatBox& b = boxes[args->primID];
  *args->bounds_o = {b.lo[0], b.lo[1], b.lo[2], 0.0f, b.hi[0], b.hi[1], b.hi[2], 0.0f};
}

/// Intersects one object in double precision and, on a nearer hit, shortens the float ray so Embree culls
/// farther nodes (Embree 3 docs, RTC_GEOMETRY_TYPE_USER: the callback updates tfar and the hit itself).
void intersect_callback(const RTCIntersectFunctionNArguments* args) {
  if (args->N != 1 || !args->valid[0]) return;  // rtcIntersect1 only: a single ray
  auto* ctx = reinterpret_cast<QueryContext*>(args->context);
  const scene::Object* object = ctx->objects[args->primID];
  if (!object->visible_to(ctx->kind)) return;
  if (!object->intersect(*ctx->ray, ctx->t_min, ctx->t_max, *ctx->hit)) return;
  ctx->t_max = ctx->hit->t;
  ctx->found = true;
  auto* rayhit = reinterpret_cast<RTCRayHit*>(args->rayhit);
  rayhit->ray.tfar = std::max(round_up(ctx->hit->t - ctx->t_offset), rayhit->ray.tnear);
  rayhit->hit.geomID = args->geomID;
  rayhit->hit.primID = args->primID;
}

FloatBox padded_box(const math::Bounds3& b, double pad) {
  FloatBox f{};
  for (int a = 0; a < 3; ++a) {
    f.lo[a] = round_down(b.lo[a] - pad);
    f.hi[a] = round_up(b.hi[a] + pad);
  }
  return f;
}

/// Whether Embree can hold the box: finite, non-empty and well inside float range (planes, and objects
/// that transforms make huge, are tested directly instead).
bool fits_float(const math::Bounds3& b) {
  constexpr double kFloatSafe = 1e30;
  return b.is_finite() && !b.empty() && max_component(abs(b.lo)) < kFloatSafe &&
         max_component(abs(b.hi)) < kFloatSafe;
}

}  // namespace

EmbreeAccelerator::EmbreeAccelerator(const scene::Scene& scene) : embree_(std::make_unique<Embree>()) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<math::Bounds3> bounds;
  double scene_size = 0;
  for (const auto& o : scene.objects) {
    const math::Bounds3 b = o->world_bounds();
    if (!fits_float(b)) {
      unbounded_.push_back(o.get());
      continue;
    }
    bounded_.push_back(o.get());
    bounds.push_back(b);
    scene_size =
        std::max({scene_size, max_component(abs(b.lo)), max_component(abs(b.hi)), max_component(b.extent())});
  }
  const double pad = kRelativePad * scene_size + std::numeric_limits<float>::min();
  for (const math::Bounds3& b : bounds) {
    const FloatBox f = padded_box(b, pad);
    embree_->boxes.push_back(f);
    embree_->scene_bounds.unite(
        math::Bounds3(math::Vec3(f.lo[0], f.lo[1], f.lo[2]), math::Vec3(f.hi[0], f.hi[1], f.hi[2])));
  }

  Embree& e = *embree_;
  e.device = rtcNewDevice(nullptr);
  if (!e.device)
    throw std::runtime_error("Embree: cannot create device (error " +
                             std::to_string(static_cast<int>(rtcGetDeviceError(nullptr))) + ")");
  rtcSetDeviceErrorFunction(e.device, &Embree::on_error, &e);
  e.scene = rtcNewScene(e.device);
  e.check("rtcNewScene");
  // ROBUST: traversal never misses a box because of its own float rounding (Embree 3 docs, RTCSceneFlags).
  rtcSetSceneFlags(e.scene, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(e.scene, RTC_BUILD_QUALITY_HIGH);
  if (!bounded_.empty()) {
    RTCGeometry geometry = rtcNewGeometry(e.device, RTC_GEOMETRY_TYPE_USER);
    e.check("rtcNewGeometry");
    rtcSetGeometryUserPrimitiveCount(geometry, static_cast<unsigned>(bounded_.size()));
    rtcSetGeometryUserData(geometry, &e.boxes);
    rtcSetGeometryBoundsFunction(geometry, &bounds_callback, nullptr);
    rtcSetGeometryIntersectFunction(geometry, &intersect_callback);
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(e.scene, geometry);
    rtcReleaseGeometry(geometry);
    e.check("building the Embree geometry");
  }
  rtcCommitScene(e.scene);
  e.check("rtcCommitScene");

  stats_.objects = scene.objects.size();
  stats_.unbounded_objects = unbounded_.size();
  stats_.build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

EmbreeAccelerator::~EmbreeAccelerator() = default;

bool EmbreeAccelerator::intersect(const math::Ray& ray, double t_min, double t_max, scene::RayKind kind,
                                  scene::SurfaceHit& hit) const {
  bool found = false;
  for (const scene::Object* o : unbounded_) {
    if (o->visible_to(kind) && o->intersect(ray, t_min, t_max, hit)) {
      t_max = hit.t;
      found = true;
    }
  }
  if (bounded_.empty()) return found;

  // Start the float ray where the double ray enters the scene box: its origin then has the scene's
  // magnitude, which bounds the rounding error the box padding must cover, and t_min < 0 needs no
  // special case (Embree requires tnear >= 0).
  double t0 = t_min;
  double t1 = t_max;
  if (!embree_->scene_bounds.clip(ray, t0, t1)) return found;
  const math::Vec3 origin = ray.at(t0);

  QueryContext ctx;
  rtcInitIntersectContext(&ctx.rtc);
  if (kind == scene::RayKind::camera) ctx.rtc.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  ctx.objects = bounded_.data();
  ctx.ray = &ray;
  ctx.t_min = t_min;
  ctx.t_max = t_max;
  ctx.t_offset = t0;
  ctx.kind = kind;
  ctx.hit = &hit;
  ctx.found = false;

  RTCRayHit rayhit{};
  rayhit.ray.org_x = static_cast<float>(origin.x);
  rayhit.ray.org_y = static_cast<float>(origin.y);
  rayhit.ray.org_z = static_cast<float>(origin.z);
  rayhit.ray.dir_x = static_cast<float>(ray.direction.x);
  rayhit.ray.dir_y = static_cast<float>(ray.direction.y);
  rayhit.ray.dir_z = static_cast<float>(ray.direction.z);
  rayhit.ray.tnear = 0.0f;
  rayhit.ray.tfar = std::isfinite(t1) ? round_up(t1 - t0) : kFloatInf;
  rayhit.ray.time = static_cast<float>(ray.time);
  rayhit.ray.mask = ~0u;
  rayhit.hit.geomID = RTC_INVALID_GEOMETRY_ID;

  const float dir_len2 = rayhit.ray.dir_x * rayhit.ray.dir_x + rayhit.ray.dir_y * rayhit.ray.dir_y +
                         rayhit.ray.dir_z * rayhit.ray.dir_z;
  const bool float_ray_ok = std::isfinite(dir_len2) && dir_len2 > 0 && std::isfinite(rayhit.ray.org_x) &&
                            std::isfinite(rayhit.ray.org_y) && std::isfinite(rayhit.ray.org_z) &&
                            !std::isnan(rayhit.ray.tfar);
  if (float_ray_ok) {
    rtcIntersect1(embree_->scene, &ctx.rtc, &rayhit);
    return found || ctx.found;
  }
  // A direction float cannot represent (over- or underflow): test every object directly.
  for (const scene::Object* o : bounded_) {
    if (o->visible_to(kind) && o->intersect(ray, t_min, t_max, hit)) {
      t_max = hit.t;
      found = true;
    }
  }
  return found;
}

}  // namespace snell::accel
