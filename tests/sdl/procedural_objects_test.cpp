// Parsing isosurface, superellipsoid and height_field (POV-Ray 3.7 reference, "Isosurface Object",
// "Superquadric Ellipsoid", "Height Field").
#include <gtest/gtest.h>

#include <zlib.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "sdl_test_util.hpp"
#include "snell/geometry/isosurface.hpp"
#include "snell/io/png_indices.hpp"
#include "snell/math/constants.hpp"

namespace snell::sdl {
namespace {

using test::error_of;
using test::parse;

bool hit_t(const scene::Scene& s, const math::Ray& ray, double& t) {
  scene::SurfaceHit hit;
  if (!s.objects.at(0)->intersect(ray, 1e-9, math::kInfinity, hit)) return false;
  t = hit.t;
  return true;
}

TEST(ProceduralObjectsParse, IsosurfaceWithSettings) {
  const auto s = parse(R"(
    isosurface { function { sqrt(x*x + y*y + z*z) - 1 } threshold 0.5 accuracy 0.0001 max_gradient 1.2
                 contained_by { sphere { 0, 2 } } open max_trace 2 translate 10*x })");
  ASSERT_EQ(s.objects.size(), 1u);
  const auto& iso = dynamic_cast<const geometry::Isosurface&>(*s.objects[0]->shape);
  EXPECT_EQ(iso.settings().threshold, 0.5);
  EXPECT_EQ(iso.settings().max_trace, 2);
  EXPECT_TRUE(iso.settings().open);
  double t = 0;
  ASSERT_TRUE(hit_t(s, {{10, 0, -5}, {0, 0, 1}, 0}, t));
  EXPECT_NEAR(t, 3.5, 1e-3);
}

TEST(ProceduralObjectsParse, IsosurfaceDefaultsToPovRays) {
  const auto s = parse("isosurface { function { x } }");
  const auto& iso = dynamic_cast<const geometry::Isosurface&>(*s.objects[0]->shape);
  EXPECT_EQ(iso.settings().accuracy, 0.001);
  EXPECT_EQ(iso.settings().max_gradient, 1.1);
  EXPECT_EQ(iso.settings().max_trace, 1);
  EXPECT_EQ(iso.bounds().lo, math::Vec3(-1));
}

TEST(ProceduralObjectsParse, IsosurfaceGradientWarningAfterRendering) {
  const auto s = parse("isosurface { function { 20 * x } }");
  double t = 0;
  ASSERT_TRUE(hit_t(s, {{0.5, 0, 0}, {-1, 0, 0}, 0}, t));
  ASSERT_EQ(s.render_notes.size(), 1u);
  EXPECT_NE(s.render_notes[0]().find("maximum gradient found was 20.000"), std::string::npos);
  EXPECT_NE(s.render_notes[0]().find("holes"), std::string::npos);
}

TEST(ProceduralObjectsParse, IsosurfaceFarTooHighGradientIsReported) {
  const auto s = parse("isosurface { function { x } max_gradient 50 }");
  double t = 0;
  ASSERT_TRUE(hit_t(s, {{0.5, 0, 0}, {-1, 0, 0}, 0}, t));
  EXPECT_NE(s.render_notes.at(0)().find("faster"), std::string::npos);
  // A well-chosen bound gives no advice.
  const auto fine = parse("isosurface { function { x } max_gradient 1.1 }");
  ASSERT_TRUE(hit_t(fine, {{0.5, 0, 0}, {-1, 0, 0}, 0}, t));
  EXPECT_EQ(fine.render_notes.at(0)(), "");
}

TEST(ProceduralObjectsParse, IsosurfaceErrors) {
  EXPECT_NE(error_of("isosurface { threshold 1 }").find("needs a function"), std::string::npos);
  EXPECT_NE(
      error_of("isosurface { function { x } contained_by { torus { 1, 0.5 } } }").find("box or a sphere"),
      std::string::npos);
  EXPECT_NE(error_of("isosurface { function { x } max_gradient 0 }").find("positive"), std::string::npos);
}

TEST(ProceduralObjectsParse, SuperellipsoidSphere) {
  const auto s = parse("superellipsoid { <1, 1> scale 2 }");
  double t = 0;
  ASSERT_TRUE(hit_t(s, {{0, 0, -5}, {0, 0, 1}, 0}, t));
  EXPECT_NEAR(t, 3, 1e-7);
}

TEST(ProceduralObjectsParse, FunctionHeightFieldPutsTheTopRowAtTheFarEdge) {
  // POV-Ray samples f(x, y, 0) with image row y = 0 at z = 1, so f = y gives height 1 - z.
  const auto s = parse("height_field { function 5, 5 { y } smooth }");
  double t = 0;
  ASSERT_TRUE(hit_t(s, {{0.5, 5, 0.25}, {0, -1, 0}, 0}, t));
  EXPECT_NEAR(t, 4.25, 1e-6);
}

void append_chunk(std::string& png, const char* type, const std::string& data) {
  const auto be = [&](unsigned v) {
    for (int s = 24; s >= 0; s -= 8) png.push_back(static_cast<char>((v >> s) & 0xff));
  };
  be(static_cast<unsigned>(data.size()));
  const std::string body = std::string(type, 4) + data;
  png += body;
  be(static_cast<unsigned>(
      crc32(0, reinterpret_cast<const Bytef*>(body.data()), static_cast<uInt>(body.size()))));
}

/// A 3 x 2 palette PNG with indices 0 10 20 / 200 210 255, rows filtered with Sub and Up.
std::filesystem::path write_palette_png() {
  std::string png = "\x89PNG\r\n\x1a\n";
  append_chunk(png, "IHDR", std::string("\0\0\0\3\0\0\0\2\x08\x03\0\0\0", 13));
  std::string palette;
  for (int i = 0; i < 256; ++i) palette += {static_cast<char>(255 - i), 0, static_cast<char>(i)};
  append_chunk(png, "PLTE", palette);
  // Sub: 0, 10-0, 20-10; Up: 200-0, 210-10, 255-20.
  const unsigned char raw[] = {1, 0, 10, 10, 2, 200, 200, 235};
  unsigned char packed[64];
  uLongf size = sizeof packed;
  compress(packed, &size, raw, sizeof raw);
  append_chunk(png, "IDAT", std::string(reinterpret_cast<char*>(packed), size));
  append_chunk(png, "IEND", "");
  const auto path = std::filesystem::temp_directory_path() / "snell_palette_test.png";
  std::ofstream(path, std::ios::binary) << png;
  return path;
}

TEST(ProceduralObjectsParse, PalettePngIndicesAreDecoded) {
  const auto path = write_palette_png();
  const auto image = io::read_png_indices(path);
  ASSERT_TRUE(image);
  EXPECT_EQ(image->width, 3);
  EXPECT_EQ(image->height, 2);
  EXPECT_EQ(image->indices, (std::vector<std::uint8_t>{0, 10, 20, 200, 210, 255}));
  // As a height field: index / 256, the file's bottom row at z = 0.
  const auto s = parse("height_field { png \"" + path.string() + "\" }");
  double t = 0;
  ASSERT_TRUE(hit_t(s, {{0, 5, 0}, {0, -1, 0}, 0}, t));
  EXPECT_NEAR(t, 5 - 200 / 256.0, 1e-6);
  std::filesystem::remove(path);
}

TEST(ProceduralObjectsParse, HeightFieldErrors) {
  EXPECT_NE(error_of("height_field { png \"no-such-file.png\" }").find("cannot find"), std::string::npos);
  EXPECT_NE(error_of("height_field { function 1, 5 { x } }").find("2 x 2"), std::string::npos);
}

}  // namespace
}  // namespace snell::sdl
