// `mesh_camera { rays_per_pixel distribution_type [max_distance] mesh {...}... [smooth] }` as POV-Ray 3.7
// parses it (reference "Mesh Camera"; its checks from POV-Ray's Parse_Mesh_Camera), and mesh triangles'
// uv_vectors, which distribution 3 needs.
#include <gtest/gtest.h>

#include "sdl_test_util.hpp"
#include "snell/scene/mesh_camera.hpp"

namespace snell::sdl {
namespace {

const char* const kTwoFaces =
    "mesh { triangle { <0,0,0>, <0,1,0>, <1,0,0> uv_vectors <0,0>, <0,1>, <1,0> }"
    " triangle { <1,1,0> <1,0,0> <0,1,0> } }";

TEST(SdlMeshCamera, ParsesCountsMeshesAndTransforms) {
  const auto cam = test::parse(std::string("#declare M = ") + kTwoFaces +
                               " camera { mesh_camera { 2 1 25 mesh { M translate <0, 0, 4> } mesh { M } }"
                               " location <0, 0, -0.01> direction <0, 0, -1> }")
                       .camera;
  ASSERT_EQ(cam.kind, scene::CameraSpec::Kind::mesh);
  ASSERT_TRUE(cam.mesh);
  EXPECT_EQ(cam.mesh->rays_per_pixel, 2);
  EXPECT_EQ(cam.mesh->distribution, 1);
  EXPECT_DOUBLE_EQ(cam.mesh->max_distance, 25);
  ASSERT_EQ(cam.mesh->meshes.size(), 2u);
  EXPECT_DOUBLE_EQ(cam.mesh->meshes[0].to_world.point({0, 0, 0}).z, 4);
  EXPECT_DOUBLE_EQ(cam.location.z, -0.01);
  EXPECT_DOUBLE_EQ(cam.direction.z, -1);
  // The first triangle's uv_vectors are kept; the second, without them, gets (0, 0) at each corner.
  const auto& data = cam.mesh->meshes[0].mesh->data();
  ASSERT_EQ(data.uv_indices.size(), 2u);
  EXPECT_DOUBLE_EQ(data.uvs[static_cast<size_t>(data.uv_indices[0][1])].v, 1);
  EXPECT_DOUBLE_EQ(data.uvs[static_cast<size_t>(data.uv_indices[1][2])].u, 0);
}

TEST(SdlMeshCamera, SmoothNeedsDistributionThree) {
  EXPECT_TRUE(test::parse(std::string("camera { mesh_camera { 1 3 ") + kTwoFaces + " smooth } }")
                  .camera.mesh->smooth);
  EXPECT_NE(test::error_of(std::string("camera { mesh_camera { 1 0 ") + kTwoFaces + " smooth } }")
                .find("distribution type 3"),
            std::string::npos);
}

TEST(SdlMeshCamera, RejectsWhatPovRayRejects) {
  const std::string mesh = kTwoFaces;
  EXPECT_NE(test::error_of("camera { mesh_camera { 0 0 " + mesh + " } }").find("rays per pixel"),
            std::string::npos);
  EXPECT_NE(test::error_of("camera { mesh_camera { 1 4 " + mesh + " } }").find("distribution"),
            std::string::npos);
  EXPECT_NE(test::error_of("camera { mesh_camera { 2 3 " + mesh + " } }").find("1 ray per pixel"),
            std::string::npos);
  EXPECT_NE(test::error_of("camera { mesh_camera { 2 0 " + mesh + " } }").find("a mesh for each ray"),
            std::string::npos);
  EXPECT_NE(test::error_of("camera { mesh_camera { 1 0 } }").find("at least one mesh"), std::string::npos);
  EXPECT_NE(test::error_of("#declare S = sphere { 0, 1 } camera { mesh_camera { 1 0 mesh { S } } }")
                .find("not a declared mesh"),
            std::string::npos);
  // Errors point at the file and line.
  EXPECT_NE(test::error_of("camera {\n mesh_camera { 1 9 " + mesh + " } }").find("test.pov:2:"),
            std::string::npos);
}

}  // namespace
}  // namespace snell::sdl
