#include "snell/accel/embree_accelerator.hpp"

#include <embree3/rtcore.h>

#include "snell/accel/embree_meshes.hpp"
#include "snell/accel/indexed_objects.hpp"
#include "snell/geometry/ray_box.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <future>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace snell::accel {

namespace {

std::once_flag g_warm_up_started;
std::shared_future<void> g_warm_up;

/// A throwaway device and an empty scene: the first commit of a process sets up Embree's scheduler.
void set_up_embree() {
  RTCDevice device = rtcNewDevice(nullptr);
  if (!device) return;  // the real build reports the error
  RTCScene scene = rtcNewScene(device);
  rtcCommitScene(scene);
  rtcReleaseScene(scene);
  rtcReleaseDevice(device);
}

void wait_for_warm_up() {
  if (g_warm_up.valid()) g_warm_up.wait();
}

using math::Bounds3;
using math::Ray;
using math::Vec3;

// Float boxes always contain the double ones: corners rounded outward (ray_box.hpp).
constexpr auto round_down = geometry::float_below;
constexpr auto round_up = geometry::float_above;

/// Per-query data for the callbacks: a struct beginning with RTCIntersectContext, passed to rtcIntersect1
/// and cast back in the callback; the Embree 3 manual (rtcInitIntersectContext) documents this extension.
struct QueryContext {
  RTCIntersectContext base;
  const Ray* ray;  // the original double-precision world ray
  double t_min;
  double t_max;    // shrinks to the best hit so far
  double t_shift;  // world t of the float ray's origin (see EmbreeAccelerator::intersect)
  double length;   // |ray.direction|: Embree's t is world distance from the shifted origin
  double pad;
  scene::RayKind kind;
  scene::SurfaceHit* hit;  // null for occlusion queries, which need only the occluder
  bool found;
  const scene::Object* occluder;  // occlusion queries: the object that ended the walk
  /// The nearest triangle crossing so far, made a hit only once the walk ends (Embree meets farther
  /// triangles first as often as not); null when the best hit so far is not a triangle's.
  const scene::Object* triangle_object;
  int triangle_face;
  geometry::Mesh::FaceCrossing triangle;
};

}  // namespace

struct EmbreeAccelerator::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::vector<const scene::Object*> bounded;
  std::vector<const scene::Object*> unbounded;
  /// Objects whose meshes Embree walks as native triangles (embree_meshes.hpp), and the object of each
  /// instance by its geometry id in `scene`.
  std::vector<const scene::Object*> native;
  std::vector<const scene::Object*> instance_objects;
  std::unique_ptr<MeshSceneCache> meshes;
  Bounds3 scene_bounds;  // union of the bounded objects' boxes, padded
  double pad = 0;        // absolute padding of every box, world units

  std::mutex error_mutex;
  std::string error;  // first error Embree reported, empty when none

  ~Impl() {
    if (scene) rtcReleaseScene(scene);
    meshes.reset();
    if (device) rtcReleaseDevice(device);
  }

  // An exception must not unwind through Embree's C frames, so the callback only records the message
  // and `check` throws it once control is back in our code.
  static void on_error(void* user, RTCError code, const char* message) {
    auto* self = static_cast<Impl*>(user);
    const std::lock_guard lock(self->error_mutex);
    if (self->error.empty())
      self->error =
          "embree error " + std::to_string(static_cast<int>(code)) + ": " + (message ? message : "");
  }
  void check(const char* what) {
    std::string message;
    {
      const std::lock_guard lock(error_mutex);
      message = error;
    }
    if (!message.empty()) throw std::runtime_error(std::string(what) + ": " + message);
  }

  static void bounds(const RTCBoundsFunctionArguments* args) {
    const auto* self = static_cast<const Impl*>(args->geometryUserPtr);
    const Bounds3 b = culling_bounds(*self->bounded[args->primID]);
    RTCBounds* out = args->bounds_o;
    out->lower_x = round_down(b.lo.x - self->pad);
    out->lower_y = round_down(b.lo.y - self->pad);
    out->lower_z = round_down(b.lo.z - self->pad);
    out->upper_x = round_up(b.hi.x + self->pad);
    out->upper_y = round_up(b.hi.y + self->pad);
    out->upper_z = round_up(b.hi.z + self->pad);
  }

  static void intersect(const RTCIntersectFunctionNArguments* args) {
    if (!args->valid[0]) return;  // rtcIntersect1 always passes N = 1
    auto* q = reinterpret_cast<QueryContext*>(args->context);
    const auto* self = static_cast<const Impl*>(args->geometryUserPtr);
    const scene::Object* object = self->bounded[args->primID];
    if (!test_object(*object, *q->ray, q->t_min, q->t_max, q->kind, *q->hit)) return;
    q->t_max = q->hit->t;
    q->found = true;
    q->triangle_object = nullptr;  // nearer than any triangle kept so far
    // Shrink Embree's float tfar so it culls boxes beyond the hit, conservatively: a box can be entered up
    // to `pad` earlier along the float ray than the double surface point it contains.
    RTCRayN* ray = RTCRayHitN_RayN(args->rayhit, 1);
    float& tfar = RTCRayN_tfar(ray, 1, 0);
    tfar = std::min(tfar, round_up((q->t_max - q->t_shift) * q->length * (1 + 1e-6) + q->pad));
    RTCHitN* hit = RTCRayHitN_HitN(args->rayhit, 1);
    RTCHitN_geomID(hit, 1, 0) = args->geomID;
    RTCHitN_primID(hit, 1, 0) = args->primID;
  }

  // Occlusion: any double-precision hit of the object within the window ends Embree's walk (tfar = -inf,
  // the Embree 3 manual's convention for an occluded ray).
  static void occluded(const RTCOccludedFunctionNArguments* args) {
    if (!args->valid[0]) return;  // rtcOccluded1 always passes N = 1
    auto* q = reinterpret_cast<QueryContext*>(args->context);
    const auto* self = static_cast<const Impl*>(args->geometryUserPtr);
    const scene::Object* object = self->bounded[args->primID];
    if (!object_blocks(*object, *q->ray, q->t_min, q->t_max, q->kind)) return;
    q->found = true;
    q->occluder = object;
    RTCRayN_tfar(args->ray, 1, 0) = -std::numeric_limits<float>::infinity();
  }

  // A native triangle Embree found in float: redone in double on the object's own ray and kept only when
  // it is visible to the ray's kind and nearer than the best double hit so far.
  static void triangle_filter(const RTCFilterFunctionNArguments* args) {
    if (!args->valid[0]) return;  // rtcIntersect1 always passes N = 1
    auto* q = reinterpret_cast<QueryContext*>(args->context);
    const auto* self = static_cast<const Impl*>(args->geometryUserPtr);
    // An instance's id in the top scene, or the geometry's own for a mesh placed in world space there.
    unsigned instance = RTCHitN_instID(args->hit, args->N, 0, 0);
    if (instance == RTC_INVALID_GEOMETRY_ID) instance = RTCHitN_geomID(args->hit, args->N, 0);
    const unsigned face = RTCHitN_primID(args->hit, args->N, 0);
    const scene::Object* object =
        instance < self->instance_objects.size() ? self->instance_objects[instance] : nullptr;
    if (!object || !object->visible_to(q->kind)) {
      args->valid[0] = 0;
      return;
    }
    const auto* mesh = static_cast<const geometry::Mesh*>(object->shape.get());
    const auto crossing = mesh->face_crossing(static_cast<int>(face), object->transform.inverse_ray(*q->ray));
    if (!crossing || !(crossing->t > q->t_min && crossing->t < q->t_max)) {
      args->valid[0] = 0;
      return;
    }
    q->triangle_object = object;
    q->triangle_face = static_cast<int>(face);
    q->triangle = *crossing;
    q->t_max = crossing->t;
    q->found = true;
    q->occluder = object;  // an occlusion query ends at this accepted hit
  }

  /// The hit of the nearest triangle crossing a query kept, if the best hit is one.
  static void finish_triangle(const QueryContext& q) {
    if (!q.triangle_object || !q.hit) return;
    const auto& mesh = static_cast<const geometry::Mesh&>(*q.triangle_object->shape);
    *q.hit = q.triangle_object->to_world(
        *q.ray, mesh.make_hit(q.triangle_face, q.triangle.t, q.triangle.b1, q.triangle.b2));
  }

  /// Fills `q` and the float ray for a query of `ray` over (t_min, t_max); false when the ray misses the
  /// scene box or cannot be walked in float (then `walkable` is false too). `hit` receives the nearest
  /// hit; null for an occlusion query.
  bool prepare(const Ray& ray, double t_min, double t_max, scene::RayKind kind, scene::SurfaceHit* hit,
               QueryContext& q, RTCRay& r, bool& walkable) const;
};

EmbreeAccelerator::EmbreeAccelerator(const scene::Scene& scene) : impl_(std::make_unique<Impl>()) {
  const auto start = std::chrono::steady_clock::now();
  Impl& s = *impl_;

  for (const auto& o : scene.objects) {
    const Bounds3 b = culling_bounds(*o);
    // Planes, and objects a transform makes unbounded, whose bounds are NaN/empty or beyond Embree's
    // float range, are tested directly.
    if (embree_can_hold(b)) {
      (native_mesh_of(*o) ? s.native : s.bounded).push_back(o.get());
      s.scene_bounds.unite(b);
    } else {
      s.unbounded.push_back(o.get());
    }
  }
  // The float ray Embree walks starts inside the scene box (see intersect), so its distance from the double
  // ray stays below a few float ulps of the scene's magnitude; padding every box by 2^-18 of that magnitude
  // (about 30 ulps) keeps each double hit inside its float box.
  if (!s.bounded.empty() || !s.native.empty()) {
    const double scale =
        std::max(max_component(math::abs(s.scene_bounds.lo)), max_component(math::abs(s.scene_bounds.hi)));
    s.pad = std::max(scale * 0x1p-18, 1e-30);
    s.scene_bounds = Bounds3(s.scene_bounds.lo - Vec3(s.pad), s.scene_bounds.hi + Vec3(s.pad));
  }

  wait_for_warm_up();  // two first-time set-ups at once would each pay it
  s.device = rtcNewDevice(nullptr);
  if (!s.device)
    throw std::runtime_error("embree: cannot create device (error " +
                             std::to_string(static_cast<int>(rtcGetDeviceError(nullptr))) + ")");
  rtcSetDeviceErrorFunction(s.device, &Impl::on_error, &s);
  s.scene = rtcNewScene(s.device);
  // ROBUST: watertight, conservative box tests (Embree API, RTC_SCENE_FLAG_ROBUST), so padding is the only
  // error budget we reason about. HIGH: a full SAH build; render time dwarfs the build.
  rtcSetSceneFlags(s.scene, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(s.scene, RTC_BUILD_QUALITY_HIGH);
  if (!s.bounded.empty()) {
    RTCGeometry geometry = rtcNewGeometry(s.device, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(geometry, static_cast<unsigned>(s.bounded.size()));
    rtcSetGeometryUserData(geometry, &s);
    rtcSetGeometryBoundsFunction(geometry, &Impl::bounds, &s);
    rtcSetGeometryIntersectFunction(geometry, &Impl::intersect);
    rtcSetGeometryOccludedFunction(geometry, &Impl::occluded);
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(s.scene, geometry);
    rtcReleaseGeometry(geometry);
  }
  s.meshes = std::make_unique<MeshSceneCache>(s.device, &s, &Impl::triangle_filter);
  // A mesh whose copies together stay small is placed in world space in the top scene, once per object:
  // Embree's walk of an instance (its ray moved into the instance's space, a second tree) cost more than
  // the triangles of mesh2.pov's four instances of 12 faces (7% of all instructions). Larger meshes stay
  // instances of one copy, built at the quality their size allows (MeshSceneCache::scene_of).
  std::unordered_map<const geometry::Shape*, size_t> users;
  for (const scene::Object* object : s.native) ++users[object->shape.get()];
  for (const scene::Object* object : s.native) {
    const auto& mesh = static_cast<const geometry::Mesh&>(*object->shape);
    const size_t copies = users[&mesh];
    const unsigned id = copies * mesh.data().faces.size() <= kWorldMeshTriangles
                            ? s.meshes->attach_in_world(s.scene, mesh, *object)
                            : attach_mesh_instance(s.device, s.scene, s.meshes->scene_of(mesh), *object);
    if (id >= s.instance_objects.size()) s.instance_objects.resize(id + 1, nullptr);
    s.instance_objects[id] = object;
  }
  rtcCommitScene(s.scene);
  s.check("embree: building the scene");

  stats_.objects = scene.objects.size();
  stats_.unbounded_objects = s.unbounded.size();
  stats_.native_triangles = s.meshes->triangles();
  stats_.mesh_instances = s.native.size();
  stats_.build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

EmbreeAccelerator::~EmbreeAccelerator() = default;

bool EmbreeAccelerator::Impl::prepare(const Ray& ray, double t_min, double t_max, scene::RayKind kind,
                                      scene::SurfaceHit* hit, QueryContext& q, RTCRay& r,
                                      bool& walkable) const {
  walkable = true;
  // An empty or NaN window (caught by the negated test) has no hits; Embree must not see NaN rays.
  if ((bounded.empty() && native.empty()) || !(t_min < t_max)) return false;
  const double length = math::length(ray.direction);
  if (!(length > 0) || !std::isfinite(length) || !math::is_finite(ray.origin)) {
    walkable = false;
    return false;
  }
  // Start the float ray where the double ray enters the scene box, not at the (possibly distant) camera:
  // float rounding of the origin then scales with the scene, which the box padding covers.
  double t0 = t_min, t1 = t_max;
  if (!scene_bounds.clip(ray, t0, t1)) return false;
  const Vec3 origin = ray.at(t0);
  const Vec3 direction = ray.direction / length;

  rtcInitIntersectContext(&q.base);
  if (kind == scene::RayKind::camera) q.base.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  q.ray = &ray;
  q.t_min = t_min;
  q.t_max = t_max;
  q.t_shift = t0;
  q.length = length;
  q.pad = pad;
  q.kind = kind;
  q.hit = hit;
  q.found = false;
  q.occluder = nullptr;
  q.triangle_object = nullptr;

  r.org_x = static_cast<float>(origin.x);
  r.org_y = static_cast<float>(origin.y);
  r.org_z = static_cast<float>(origin.z);
  r.dir_x = static_cast<float>(direction.x);
  r.dir_y = static_cast<float>(direction.y);
  r.dir_z = static_cast<float>(direction.z);
  r.tnear = 0;
  r.tfar = round_up((t1 - t0) * length * (1 + 1e-6) + pad);
  r.time = static_cast<float>(ray.time);
  r.mask = ~0u;
  r.id = 0;
  r.flags = 0;
  return true;
}

bool EmbreeAccelerator::intersect(const Ray& ray, double t_min, double t_max, scene::RayKind kind,
                                  scene::SurfaceHit& hit) const {
  const Impl& s = *impl_;
  bool found = test_all(s.unbounded, ray, t_min, t_max, kind, hit);
  QueryContext q;  // every field is set by prepare: value-initialising both cost a rep stos a ray
  RTCRayHit rh;
  bool walkable;
  if (!s.prepare(ray, t_min, t_max, kind, &hit, q, rh.ray, walkable)) {
    if (walkable) return found;
    // Nothing Embree can walk; fall back to testing every object, still in double precision.
    const bool any_bounded = test_all(s.bounded, ray, t_min, t_max, kind, hit);
    return test_all(s.native, ray, t_min, t_max, kind, hit) || any_bounded || found;
  }
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(s.scene, &q.base, &rh);
  Impl::finish_triangle(q);
  return found || q.found;
}

const scene::Object* EmbreeAccelerator::occluder(const Ray& ray, double t_min, double t_max,
                                                 scene::RayKind kind) const {
  const Impl& s = *impl_;
  for (const scene::Object* o : s.unbounded)
    if (object_blocks(*o, ray, t_min, t_max, kind)) return o;
  QueryContext q;
  RTCRay r;
  bool walkable;
  if (!s.prepare(ray, t_min, t_max, kind, nullptr, q, r, walkable)) {
    if (walkable) return nullptr;
    for (const auto* objects : {&s.bounded, &s.native})
      for (const scene::Object* o : *objects)
        if (object_blocks(*o, ray, t_min, t_max, kind)) return o;
    return nullptr;
  }
  rtcOccluded1(s.scene, &q.base, &r);
  return q.occluder;
}

void warm_up_embree() {
  std::call_once(g_warm_up_started,
                 [] { g_warm_up = std::async(std::launch::async, set_up_embree).share(); });
}

}  // namespace snell::accel
