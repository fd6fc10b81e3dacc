// Mesh camera rays worked out by hand for small grids of triangles, following the POV-Ray 3.7 reference
// ("Mesh Camera") and POV-Ray's tracepixel.cpp: the ray of pixel (column, row) leaves the centroid of face
// row * width + column, along the face normal cross(P3 - P1, P2 - P1), moved location.z along it; direction.z
// < 0 reverses it; the mesh's transform carries both (the normal by the inverse transpose).
#include "snell/scene/mesh_camera.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "snell/scene/camera.hpp"

namespace snell::scene {
namespace {

using math::Vec3;

void expect_vec(const Vec3& got, const Vec3& want, double tol = 1e-12) {
  EXPECT_NEAR(got.x, want.x, tol);
  EXPECT_NEAR(got.y, want.y, tol);
  EXPECT_NEAR(got.z, want.z, tol);
}

/// `count` unit right triangles in a row along x, at z = `z`; face i has corners (i, 0), (i, 1), (i + 1, 0),
/// so its normal cross(P3 - P1, P2 - P1) is +z and its centroid (i + 1/3, 1/3, z).
std::shared_ptr<const geometry::Mesh> strip(int count, double z = 0) {
  geometry::MeshData d;
  for (int i = 0; i < count; ++i) {
    const int v = static_cast<int>(d.vertices.size());
    d.vertices.push_back({double(i), 0, z});
    d.vertices.push_back({double(i), 1, z});
    d.vertices.push_back({double(i + 1), 0, z});
    d.faces.push_back({v, v + 1, v + 2});
  }
  return std::make_shared<geometry::Mesh>(d);
}

CameraSpec mesh_spec(MeshCameraSpec m, double location_z = 0, double direction_z = 1) {
  CameraSpec s;
  s.kind = CameraSpec::Kind::mesh;
  s.location = {7, 8, location_z};  // x and y are not used by a mesh camera
  s.direction = {0, 0, direction_z};
  s.mesh = std::make_shared<MeshCameraSpec>(std::move(m));
  return s;
}

/// Image point of pixel (column, row) centre in a width x height image.
std::optional<math::Ray> pixel_ray(const Camera& cam, int column, int row, int width, int height, int n = 0) {
  return cam.generate_numbered_ray((column + 0.5) / width, (row + 0.5) / height, n, 0);
}

TEST(MeshCamera, DistributionZeroUsesFacePerPixelFromItsCentroid) {
  MeshCameraSpec m;
  m.meshes.push_back({strip(6), {}});
  const auto cam = make_camera(mesh_spec(m, 0.5), 3, 2);
  // Pixel (2, 1) of a 3 x 2 image is face 5: centroid (5 1/3, 1/3, 0), moved 0.5 along +z.
  const auto r = pixel_ray(*cam, 2, 1, 3, 2);
  ASSERT_TRUE(r);
  expect_vec(r->origin, {5 + 1.0 / 3, 1.0 / 3, 0.5});
  expect_vec(r->direction, {0, 0, 1});
  expect_vec(pixel_ray(*cam, 0, 0, 3, 2)->origin, {1.0 / 3, 1.0 / 3, 0.5});
  // Anywhere inside the pixel gives the same ray (POV-Ray floors the position).
  expect_vec(cam->generate_ray(0.99, 0.51, 0)->origin, r->origin);
}

TEST(MeshCamera, NegativeDirectionZReversesButOffsetFollowsTheNormal) {
  MeshCameraSpec m;
  m.meshes.push_back({strip(1), {}});
  const auto r = make_camera(mesh_spec(m, 0.25, -1), 1, 1)->generate_ray(0.5, 0.5, 0);
  ASSERT_TRUE(r);
  expect_vec(r->direction, {0, 0, -1});
  expect_vec(r->origin, {1.0 / 3, 1.0 / 3, 0.25});
}

TEST(MeshCamera, PixelsWithoutAFaceTraceNothing) {
  MeshCameraSpec m;
  m.meshes.push_back({strip(3), {}});
  const auto cam = make_camera(mesh_spec(m), 2, 2);
  EXPECT_TRUE(pixel_ray(*cam, 0, 1, 2, 2));   // face 2
  EXPECT_FALSE(pixel_ray(*cam, 1, 1, 2, 2));  // face 3 does not exist
}

TEST(MeshCamera, DegenerateTrianglesTakeNoFaceIndex) {
  geometry::MeshData d;
  d.vertices = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {5, 0, 0}, {5, 1, 0}, {6, 0, 0}};
  d.faces = {{0, 1, 2}, {3, 4, 5}};  // the first is a line: POV-Ray drops it
  MeshCameraSpec m;
  m.meshes.push_back({std::make_shared<geometry::Mesh>(d), {}});
  const auto r = make_camera(mesh_spec(m), 1, 1)->generate_ray(0.5, 0.5, 0);
  ASSERT_TRUE(r);
  expect_vec(r->origin, {5 + 1.0 / 3, 1.0 / 3, 0});
}

TEST(MeshCamera, MeshTransformMovesOriginAndTurnsNormalByInverseTranspose) {
  // Face (0,0,0), (0,1,0), (1,0,-1): normal cross((1,0,-1), (0,1,0)) = (1, 0, 1) / sqrt 2, centroid
  // (1/3, 1/3, -1/3). Scaled by 2 along x, the triangle's own normal is cross((2,0,-1), (0,1,0)) = (1, 0, 2).
  geometry::MeshData d;
  d.vertices = {{0, 0, 0}, {0, 1, 0}, {1, 0, -1}};
  d.faces = {{0, 1, 2}};
  MeshCameraSpec m;
  const math::Transform t = math::Transform::translate({0, 0, 10}) * math::Transform::scale({2, 1, 1});
  m.meshes.push_back({std::make_shared<geometry::Mesh>(d), t});
  const double offset = std::sqrt(2.0);  // moves the centroid by (1, 0, 1) in object space
  const auto r = make_camera(mesh_spec(m, offset), 1, 1)->generate_ray(0.5, 0.5, 0);
  ASSERT_TRUE(r);
  expect_vec(r->origin, {2 * (1.0 / 3 + 1), 1.0 / 3, -1.0 / 3 + 1 + 10});
  expect_vec(r->direction, normalize(Vec3(1, 0, 2)));
}

TEST(MeshCamera, DistributionOneSumsMeshesAndStepsByTheImagePerRay) {
  // 2 x 1 image, two meshes of two faces: ray n of pixel p uses face p + n * 2 of the summed list (reference
  // "Mesh Camera", distribution #1).
  MeshCameraSpec m;
  m.distribution = 1;
  m.rays_per_pixel = 2;
  m.meshes.push_back({strip(2, 0), {}});
  m.meshes.push_back({strip(2, 5), {}});
  const auto cam = make_camera(mesh_spec(m), 2, 1);
  EXPECT_EQ(cam->rays_per_point(), 2);
  expect_vec(pixel_ray(*cam, 1, 0, 2, 1, 0)->origin, {1 + 1.0 / 3, 1.0 / 3, 0});
  expect_vec(pixel_ray(*cam, 0, 0, 2, 1, 1)->origin, {1.0 / 3, 1.0 / 3, 5});
  expect_vec(pixel_ray(*cam, 1, 0, 2, 1, 1)->origin, {1 + 1.0 / 3, 1.0 / 3, 5});
}

TEST(MeshCamera, DistributionZeroTakesOneMeshPerRay) {
  MeshCameraSpec m;
  m.rays_per_pixel = 2;
  m.meshes.push_back({strip(1, 0), {}});
  m.meshes.push_back({strip(1, 3), {}});
  const auto cam = make_camera(mesh_spec(m), 1, 1);
  expect_vec(cam->generate_numbered_ray(0.5, 0.5, 1, 0)->origin, {1.0 / 3, 1.0 / 3, 3});
}

TEST(MeshCamera, DistributionTwoPutsMeshesSideBySide) {
  // 4 x 2 image, two meshes: columns 0-1 use mesh 0, columns 2-3 mesh 1; the face is row * 2 + column with
  // the column counted from the image's left edge, as POV-Ray computes it.
  MeshCameraSpec m;
  m.distribution = 2;
  m.meshes.push_back({strip(8, 0), {}});
  m.meshes.push_back({strip(8, 4), {}});
  const auto cam = make_camera(mesh_spec(m), 4, 2);
  expect_vec(pixel_ray(*cam, 1, 1, 4, 2)->origin, {3 + 1.0 / 3, 1.0 / 3, 0});  // mesh 0, face 3
  expect_vec(pixel_ray(*cam, 2, 0, 4, 2)->origin, {2 + 1.0 / 3, 1.0 / 3, 4});  // mesh 1, face 2
  expect_vec(pixel_ray(*cam, 3, 1, 4, 2)->origin, {5 + 1.0 / 3, 1.0 / 3, 4});  // mesh 1, face 5
}

/// The square [0,2] x [0,2] at z = 0 as two triangles whose uv is position / 2.
geometry::MeshData uv_square() {
  geometry::MeshData d;
  d.vertices = {{0, 0, 0}, {0, 2, 0}, {2, 0, 0}, {2, 2, 0}};
  d.faces = {{0, 1, 2}, {3, 2, 1}};
  d.uvs = {{0, 0}, {0, 1}, {1, 0}, {1, 1}};
  d.uv_indices = d.faces;
  return d;
}

TEST(MeshCamera, DistributionThreeFindsThePointWithThePixelsUv) {
  MeshCameraSpec m;
  m.distribution = 3;
  m.meshes.push_back({std::make_shared<geometry::Mesh>(uv_square()), {}});
  const auto cam = make_camera(mesh_spec(m, 0.1), 10, 10);
  // Image point (0.25, 0.25) is uv (0.25, 0.75) (v grows upward): position (0.5, 1.5), in the first face.
  auto r = cam->generate_ray(0.25, 0.25, 0);
  ASSERT_TRUE(r);
  expect_vec(r->origin, {0.5, 1.5, 0.1});
  expect_vec(r->direction, {0, 0, 1});
  // Continuous: no snapping to pixels; (0.9, 0.2) is uv (0.9, 0.8), in the second face.
  r = cam->generate_ray(0.9, 0.2, 0);
  ASSERT_TRUE(r);
  expect_vec(r->origin, {1.8, 1.6, 0.1});
}

TEST(MeshCamera, DistributionThreeSmoothInterpolatesVertexNormals) {
  geometry::MeshData d = uv_square();
  const double s = std::sqrt(0.5);
  d.normals = {{0, 0, 1}, {0, s, s}, {s, 0, s}, {0, 0, 1}};
  d.normal_indices = d.faces;
  MeshCameraSpec m;
  m.distribution = 3;
  m.smooth = true;
  m.meshes.push_back({std::make_shared<geometry::Mesh>(d), {}});
  // uv (0.25, 0.25) = position (0.5, 0.5) in face 0: barycentric 1/2, 1/4, 1/4 on corners 0, 1, 2.
  const auto r = make_camera(mesh_spec(m), 4, 4)->generate_ray(0.25, 0.75, 0);
  ASSERT_TRUE(r);
  expect_vec(r->origin, {0.5, 0.5, 0});
  expect_vec(r->direction, normalize(Vec3(0.25 * s, 0.25 * s, 0.5 + 0.5 * s)));
  // Without smooth, the face normal.
  m.smooth = false;
  expect_vec(make_camera(mesh_spec(m), 4, 4)->generate_ray(0.25, 0.75, 0)->direction, {0, 0, 1});
}

TEST(MeshCamera, UvOutsideEveryFaceTracesNothing) {
  geometry::MeshData d = uv_square();
  d.faces.pop_back();
  d.uv_indices.pop_back();
  MeshCameraSpec m;
  m.distribution = 3;
  m.meshes.push_back({std::make_shared<geometry::Mesh>(d), {}});
  EXPECT_FALSE(make_camera(mesh_spec(m), 4, 4)->generate_ray(0.9, 0.1, 0));  // uv (0.9, 0.9)
}

TEST(MeshCamera, MaxDistanceIsReported) {
  MeshCameraSpec m;
  m.max_distance = 3;
  m.meshes.push_back({strip(1), {}});
  EXPECT_DOUBLE_EQ(make_camera(mesh_spec(m), 1, 1)->max_distance(), 3);
  m.max_distance = 0;
  EXPECT_TRUE(std::isinf(make_camera(mesh_spec(m), 1, 1)->max_distance()));
}

}  // namespace
}  // namespace snell::scene
