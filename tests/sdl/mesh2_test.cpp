// mesh2 as POV-Ray 3.7 reads it ("Mesh2" in its reference): indexed lists with counts, optional commas,
// normals paired with vertices, and clear errors for counts and indices that do not fit.
#include <gtest/gtest.h>

#include "sdl_test_util.hpp"
#include "snell/geometry/mesh.hpp"

using namespace snell;

namespace {

const geometry::MeshData& mesh_of(const scene::Scene& s) {
  EXPECT_EQ(s.objects.size(), 1u);
  const auto* mesh = dynamic_cast<const geometry::Mesh*>(s.objects.front()->shape.get());
  EXPECT_NE(mesh, nullptr);
  return mesh->data();
}

TEST(SdlMesh2, ListsWithCountsBuildTheMesh) {
  const scene::Scene s = sdl::test::parse(R"(
mesh2 {
  vertex_vectors { 4, <0,0,0>, <1,0,0> <0,1,0>, <1,1,0> }
  normal_vectors { 4, z, z, z, z }
  uv_vectors { 3 <0,0>, <1,0> <0,1> }
  face_indices { 2, <0,1,2>, <1,3,2> }
  uv_indices { 2, <0,1,2> <1,0,2> }
  inside_vector y
})");
  const geometry::MeshData& d = mesh_of(s);
  EXPECT_EQ(d.vertices.size(), 4u);
  ASSERT_EQ(d.faces.size(), 2u);
  EXPECT_EQ(d.faces[1], (std::array<int, 3>{1, 3, 2}));
  EXPECT_EQ(d.normal_indices, d.faces);  // normals pair with vertices without normal_indices
  EXPECT_EQ(d.uv_indices.size(), 2u);
  EXPECT_TRUE(d.inside_vector.has_value());
  // A ray down the z axis through the first face hits it at t = 1.
  math::Ray ray({0.25, 0.25, -1}, {0, 0, 1});
  scene::SurfaceHit hit;
  EXPECT_TRUE(s.objects.front()->intersect(ray, 1e-9, 1e9, hit));
  EXPECT_NEAR(hit.t, 1.0, 1e-12);
}

TEST(SdlMesh2, CountsAndIndicesAreChecked) {
  EXPECT_NE(
      sdl::test::error_of("mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0> } face_indices { 1, <0,1,2> } }")
          .find("holds 2 items, its count says 3"),
      std::string::npos);
  EXPECT_NE(sdl::test::error_of(
                "mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> } face_indices { 1, <0,1,3> } }")
                .find("index 3"),
            std::string::npos);
  EXPECT_NE(sdl::test::error_of("mesh2 { vertex_vectors { 1, <0,0,0>, <1,0,0> } }").find("more items"),
            std::string::npos);
  EXPECT_NE(sdl::test::error_of("mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> } }").find("no face"),
            std::string::npos);
}

}  // namespace
