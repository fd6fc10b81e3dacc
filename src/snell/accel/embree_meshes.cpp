#include "snell/accel/embree_meshes.hpp"

#include <cmath>

namespace snell::accel {

using math::Vec3;

bool embree_can_hold(const math::Bounds3& box) {
  return box.is_finite() && !box.empty() && max_component(math::abs(box.lo)) < kMaxEmbreeCoordinate &&
         max_component(math::abs(box.hi)) < kMaxEmbreeCoordinate;
}

const geometry::Mesh* native_mesh_of(const scene::Object& object) {
  if (object.csg || object.motion || object.bounded_by || object.flags.inverse) return nullptr;
  const auto* mesh = dynamic_cast<const geometry::Mesh*>(object.shape.get());
  if (!mesh || mesh->data().faces.size() < kNativeMeshMinFaces) return nullptr;
  return embree_can_hold(mesh->bounds()) ? mesh : nullptr;
}

MeshSceneCache::~MeshSceneCache() {
  for (auto& [mesh, scene] : scenes_) rtcReleaseScene(scene);
}

namespace {

/// A committed Embree geometry of `data`'s triangles, its vertices placed by `placement` when given (a mesh
/// walked in world space) and rounded to float; the filter redoes each candidate in double.
RTCGeometry new_triangle_geometry(RTCDevice device, const geometry::MeshData& data,
                                  const math::Transform* placement, void* user_data,
                                  RTCFilterFunctionN filter) {
  RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), data.vertices.size()));
  if (vertices) {
    for (size_t i = 0; i < data.vertices.size(); ++i) {
      const Vec3 v = placement ? placement->point(data.vertices[i]) : data.vertices[i];
      vertices[3 * i] = static_cast<float>(v.x);
      vertices[3 * i + 1] = static_cast<float>(v.y);
      vertices[3 * i + 2] = static_cast<float>(v.z);
    }
  }
  // The index triples are shared, not copied (12 bytes a triangle saved): the Mesh checked them to be in
  // range and outlives the accelerator, as the scene does.
  static_assert(sizeof(data.faces[0]) == 3 * sizeof(unsigned));
  rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, data.faces.data(), 0,
                             3 * sizeof(unsigned), data.faces.size());
  rtcSetGeometryUserData(geometry, user_data);
  rtcSetGeometryIntersectFilterFunction(geometry, filter);
  rtcSetGeometryOccludedFilterFunction(geometry, filter);
  rtcCommitGeometry(geometry);
  return geometry;
}

}  // namespace

RTCScene MeshSceneCache::scene_of(const geometry::Mesh& mesh) {
  if (const auto found = scenes_.find(&mesh); found != scenes_.end()) return found->second;
  const geometry::MeshData& data = mesh.data();
  RTCGeometry geometry = new_triangle_geometry(device_, data, nullptr, user_data_, filter_);
  RTCScene scene = rtcNewScene(device_);
  rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
  // Medium quality: a high-quality (spatial split) build of ten million triangles costs gigabytes.
  rtcSetSceneBuildQuality(scene,
                          data.faces.size() > 1000000 ? RTC_BUILD_QUALITY_MEDIUM : RTC_BUILD_QUALITY_HIGH);
  rtcAttachGeometry(scene, geometry);
  rtcReleaseGeometry(geometry);
  rtcCommitScene(scene);
  scenes_.emplace(&mesh, scene);
  triangles_ += data.faces.size();
  return scene;
}

unsigned MeshSceneCache::attach_in_world(RTCScene top, const geometry::Mesh& mesh,
                                         const scene::Object& object) {
  RTCGeometry geometry = new_triangle_geometry(device_, mesh.data(), &object.transform, user_data_, filter_);
  const unsigned id = rtcAttachGeometry(top, geometry);
  rtcReleaseGeometry(geometry);
  triangles_ += mesh.data().faces.size();
  return id;
}

unsigned attach_mesh_instance(RTCDevice device, RTCScene top, RTCScene mesh_scene,
                              const scene::Object& object) {
  RTCGeometry instance = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_INSTANCE);
  rtcSetGeometryInstancedScene(instance, mesh_scene);
  // Column-major 3x4: the images of the axes, then of the origin (independent of Matrix4's layout).
  const Vec3 columns[4] = {object.transform.vector({1, 0, 0}), object.transform.vector({0, 1, 0}),
                           object.transform.vector({0, 0, 1}), object.transform.point({0, 0, 0})};
  float matrix[12];
  for (int c = 0; c < 4; ++c) {
    matrix[3 * c] = static_cast<float>(columns[c].x);
    matrix[3 * c + 1] = static_cast<float>(columns[c].y);
    matrix[3 * c + 2] = static_cast<float>(columns[c].z);
  }
  rtcSetGeometryTransform(instance, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, matrix);
  rtcCommitGeometry(instance);
  const unsigned id = rtcAttachGeometry(top, instance);
  rtcReleaseGeometry(instance);
  return id;
}

}  // namespace snell::accel
