// `mesh { "file" }` (snell extension) through Assimp: model files written here, checked for triangle counts,
// bounds, normals and material colours, and for clear errors on missing, degenerate or lying files.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "sdl_test_util.hpp"
#include "snell/geometry/mesh.hpp"
#include "snell/io/mesh_import.hpp"

using namespace snell;

namespace {

/// A per-process folder, since ctest runs test binaries in parallel; removed when the binary exits.
std::filesystem::path test_dir() {
  struct Folder {
    std::filesystem::path path =
        std::filesystem::temp_directory_path() / ("snell_mesh_import_" + std::to_string(getpid()));
    Folder() { std::filesystem::create_directories(path); }
    ~Folder() {
      std::error_code ec;
      std::filesystem::remove_all(path, ec);
    }
  };
  static const Folder folder;
  return folder.path;
}

std::string write_file(const std::string& name, const std::string& bytes) {
  const auto path = test_dir() / name;
  std::ofstream(path, std::ios::binary) << bytes;
  return path.string();
}

const geometry::MeshData& mesh_data(const scene::Object& o) {
  const auto* mesh = dynamic_cast<const geometry::Mesh*>(o.shape.get());
  EXPECT_NE(mesh, nullptr);
  static const geometry::MeshData empty;
  return mesh ? mesh->data() : empty;
}

/// `mesh { "path" modifiers }` parsed, checked to be one mesh of `faces` triangles.
scene::Scene parse_one_mesh(const std::string& path, size_t faces, const std::string& modifiers = "") {
  scene::Scene s = sdl::test::parse("mesh { \"" + path + "\" " + modifiers + " }");
  EXPECT_EQ(s.objects.size(), 1u);
  if (!s.objects.empty()) {
    EXPECT_EQ(mesh_data(*s.objects[0]).faces.size(), faces);
  }
  return s;
}

// A unit tetrahedron with corners at the origin and on the three axes: four faces.
const char* const kTetrahedronPly = R"(ply
format ascii 1.0
element vertex 4
property float x
property float y
property float z
element face 4
property list uchar int vertex_indices
end_header
0 0 0
1 0 0
0 1 0
0 0 1
3 0 2 1
3 0 1 3
3 0 3 2
3 1 2 3
)";

TEST(SdlMeshImport, PlyTetrahedronHasFourFacesAndUnitBounds) {
  const std::string ply = write_file("tetra.ply", kTetrahedronPly);
  const scene::Scene s = parse_one_mesh(ply, 4, "translate <1,0,0>");
  ASSERT_EQ(s.objects.size(), 1u);
  const math::Bounds3 b = s.objects[0]->world_bounds();
  EXPECT_NEAR(b.lo.x, 1, 1e-6);
  EXPECT_NEAR(b.hi.x, 2, 1e-6);
  EXPECT_NEAR(b.lo.y, 0, 1e-6);
  EXPECT_NEAR(b.hi.z, 1, 1e-6);
  // The slanted face x + y + z = 1 (shifted by the translate) is hit at t = 1/3 along the diagonal from
  // (1,0,0)+(1,1,1)... : from (1.1,0.1,0.1)+s(1,1,1)/sqrt3 the plane (x-1)+y+z = 1 lies at s = 0.7/sqrt3.
  const math::Vec3 dir = math::Vec3{1, 1, 1} / std::sqrt(3.0);
  math::Ray ray({1.1, 0.1, 0.1}, dir);
  scene::SurfaceHit hit;
  ASSERT_TRUE(s.objects[0]->intersect(ray, 1e-9, 1e9, hit));
  EXPECT_NEAR(hit.t, 0.7 / std::sqrt(3.0), 1e-6);
  EXPECT_NEAR(std::fabs(hit.normal.x), 1 / std::sqrt(3.0), 1e-6);
  EXPECT_NEAR(std::fabs(hit.normal.z), 1 / std::sqrt(3.0), 1e-6);
}

TEST(SdlMeshImport, BinaryPlyIsReadDirectlyAndPolygonsBecomeFans) {
  // Two vertices with double x and an extra ignored property, a quad (2 triangles) and a triangle.
  std::string bytes =
      "ply\nformat binary_little_endian 1.0\nelement vertex 5\nproperty double x\nproperty float y\n"
      "property float z\nproperty uchar quality\nelement face 2\nproperty list uchar uint vertex_indices\n"
      "end_header\n";
  auto put = [&](const auto v) { bytes.append(reinterpret_cast<const char*>(&v), sizeof v); };
  const float corners[5][3] = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}, {0, 0, -3}};
  for (const auto& c : corners) {
    put(double(c[0]));
    put(c[1]);
    put(c[2]);
    put(std::uint8_t{7});
  }
  put(std::uint8_t{4});
  for (std::uint32_t i : {0u, 1u, 2u, 3u}) put(i);
  put(std::uint8_t{3});
  for (std::uint32_t i : {0u, 1u, 4u}) put(i);
  const std::string ply = write_file("direct.ply", bytes);
  const scene::Scene s = parse_one_mesh(ply, 3);
  ASSERT_EQ(s.objects.size(), 1u);
  const math::Bounds3 b = s.objects[0]->world_bounds();
  EXPECT_NEAR(b.hi.x, 2, 1e-9);
  EXPECT_NEAR(b.lo.z, -3, 1e-9);
  math::Ray ray({1.5, 0.9, -1}, {0, 0, 1});  // inside the quad's second fan triangle (0, 2, 3)
  scene::SurfaceHit hit;
  ASSERT_TRUE(s.objects[0]->intersect(ray, 1e-9, 1e9, hit));
  EXPECT_NEAR(hit.t, 1, 1e-9);

  const std::string cut = write_file("cut.ply", bytes.substr(0, bytes.size() - 5));
  EXPECT_NE(sdl::test::error_of("mesh { \"" + cut + "\" }").find("cut short"), std::string::npos);
  std::string wrong_index = bytes;
  wrong_index[wrong_index.size() - 4] = 9;  // the last index names vertex 9 of 5
  const std::string bad = write_file("index.ply", wrong_index);
  EXPECT_NE(sdl::test::error_of("mesh { \"" + bad + "\" }").find("names vertex 9 of 5"), std::string::npos);
}

TEST(SdlMeshImport, ObjMaterialsBecomeTextures) {
  write_file("two.mtl", R"(newmtl red
Kd 1 0 0
Ks 0.5 0.5 0.5
Ns 20
d 0.75
newmtl blue
Kd 0 0 1
)");
  // A quad (two triangles after triangulation) in red and one triangle in blue.
  const std::string obj = write_file("two.obj", R"(mtllib two.mtl
v 0 0 0
v 2 0 0
v 2 1 0
v 0 1 0
v 0 0 3
usemtl red
f 1 2 3 4
usemtl blue
f 1 2 5
)");
  const scene::Scene s = sdl::test::parse("mesh { \"" + obj + "\" }");
  ASSERT_EQ(s.objects.size(), 2u);
  size_t triangles = 0;
  bool saw_red = false, saw_blue = false;
  for (const auto& o : s.objects) {
    triangles += mesh_data(*o).faces.size();
    const material::Rgbft c = sdl::test::solid_color(*o);
    if (c.rgb.r == 1 && c.rgb.b == 0) {
      saw_red = true;
      EXPECT_EQ(mesh_data(*o).faces.size(), 2u);
      EXPECT_NEAR(c.transmit, 0.25, 1e-6);  // 1 - d
      EXPECT_NEAR(o->texture->finish.phong, 0.5, 1e-6);
      EXPECT_NEAR(o->texture->finish.phong_size, 20, 1e-6);
    } else if (c.rgb.b == 1 && c.rgb.r == 0) {
      saw_blue = true;
      EXPECT_EQ(c.transmit, 0);
    }
  }
  EXPECT_EQ(triangles, 3u);
  EXPECT_TRUE(saw_red && saw_blue);

  // The scene's own texture replaces the file's materials.
  const scene::Scene own = sdl::test::parse("mesh { \"" + obj + "\" pigment { rgb <0,1,0> } }");
  ASSERT_EQ(own.objects.size(), 2u);
  for (const auto& o : own.objects) EXPECT_EQ(sdl::test::solid_color(*o).rgb.g, 1);
}

TEST(SdlMeshImport, BinaryStlTriangleKeepsItsPlane) {
  std::string bytes(80, ' ');
  auto put_u32 = [&](std::uint32_t v) { bytes.append(reinterpret_cast<const char*>(&v), 4); };
  auto put_f = [&](float v) { bytes.append(reinterpret_cast<const char*>(&v), 4); };
  put_u32(1);
  for (float v : {0.f, 0.f, 1.f, 0.f, 0.f, 0.5f, 1.f, 0.f, 0.5f, 0.f, 1.f, 0.5f}) put_f(v);
  bytes.append(2, '\0');
  const std::string stl = write_file("one.stl", bytes);
  const scene::Scene s = parse_one_mesh(stl, 1);
  ASSERT_EQ(s.objects.size(), 1u);
  math::Ray ray({0.2, 0.2, -1}, {0, 0, 1});
  scene::SurfaceHit hit;
  ASSERT_TRUE(s.objects[0]->intersect(ray, 1e-9, 1e9, hit));
  EXPECT_NEAR(hit.t, 1.5, 1e-6);
  EXPECT_NEAR(std::fabs(hit.normal.z), 1, 1e-6);

  // A binary STL whose count claims a billion triangles in 134 bytes fails before anything is allocated.
  std::string lying = bytes;
  const std::uint32_t billion = 1000000000u;
  std::memcpy(lying.data() + 80, &billion, 4);
  const std::string bad = write_file("lying.stl", lying);
  EXPECT_NE(sdl::test::error_of("mesh { \"" + bad + "\" }").find("claims 1000000000 triangles"),
            std::string::npos);
}

TEST(SdlMeshImport, BadFilesGiveLocatedErrors) {
  const std::string missing = sdl::test::error_of("\nmesh {  \"no_such_model.obj\" }");
  EXPECT_NE(missing.find("test.pov:2:9: error: cannot find mesh file"), std::string::npos) << missing;

  std::string ply = kTetrahedronPly;
  ply.replace(ply.find("element face 4"), 14, "element face 1000000000");
  const std::string lying = write_file("lying.ply", ply);
  EXPECT_NE(sdl::test::error_of("mesh { \"" + lying + "\" }").find("PLY header claims"), std::string::npos);

  const std::string no_faces = write_file("points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
  EXPECT_NE(sdl::test::error_of("mesh { \"" + no_faces + "\" }").find("cannot import mesh file"),
            std::string::npos);

  const std::string garbage = write_file("garbage.obj", std::string("\x01\x02\x03 not a model", 17));
  EXPECT_NE(sdl::test::error_of("mesh { \"" + garbage + "\" }").find("cannot import mesh file"),
            std::string::npos);

  std::string nan_ply = kTetrahedronPly;
  // Assimp reads the text "nan" as a number of its own choosing; an overflowing 1e999 becomes infinity.
  nan_ply.replace(nan_ply.find("0 1 0\n"), 5, "0 1e999 0");
  const std::string nan_file = write_file("nan.ply", nan_ply);
  const std::string nan_error = sdl::test::error_of("mesh { \"" + nan_file + "\" }");
  EXPECT_NE(nan_error.find("is not a finite number"), std::string::npos) << nan_error;
}

}  // namespace
