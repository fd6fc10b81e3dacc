// Parsing `lsystem { }` and the generated height fields (docs/procedural.md).
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>

#include "sdl_test_util.hpp"
#include "snell/geometry/branch_set.hpp"
#include "snell/io/image_file.hpp"
#include "snell/math/constants.hpp"

namespace snell::sdl {
namespace {

using test::error_of;
using test::parse;

TEST(LSystemBlock, BushBecomesOneBranchSetPerColour) {
  // Mariano's bush at n = 2: 64 segments (reference-values.md section 4), all of colour 0.
  const auto s = parse(R"(lsystem { axiom "++++F" rule "F" "FF-[-F+F+F]+[+F-F-F]" angle_divisions 16
                                    iterations 2 width 0.1 taper 0.8 pigment { rgb 1 } })");
  ASSERT_EQ(s.objects.size(), 1u);
  const auto& set = dynamic_cast<const geometry::BranchSet&>(*s.objects[0]->shape);
  EXPECT_EQ(set.size(), 64u);
  // The trunk: 4 unit steps up the y axis, radius 0.05: a ray along x at y = 1 meets it at x = -0.05.
  scene::SurfaceHit hit;
  ASSERT_TRUE(s.objects[0]->intersect({{-5, 1, 0}, {1, 0, 0}, 0}, 1e-9, math::kInfinity, hit));
  EXPECT_NEAR(hit.t, 5 - 0.05, 1e-6);
}

TEST(LSystemBlock, PaletteLeavesTransformsAndSharing) {
  const auto s = parse(R"(
    #declare Plant = lsystem { axiom "F'F~" rule "X" "X" angle 90 width 0.2
                               palette { texture { pigment { rgb x } } texture { pigment { rgb y } } }
                               leaf { sphere { 0, 0.1 } pigment { rgb z } } }
    object { Plant translate 10*z }
    object { Plant translate 20*z }
    lsystem { axiom "F'F~" rule "X" "X" angle 90 width 0.2 })");
  // Each plant: two branch sets (colours 0 and 1) and one leaf at the end (2, 0, 0).
  ASSERT_EQ(s.objects.size(), 8u);
  EXPECT_EQ(s.objects[0]->shape.get(), s.objects[3]->shape.get());  // copies share their branches
  EXPECT_EQ(s.objects[0]->shape.get(), s.objects[6]->shape.get());  // an identical block shares them too
  EXPECT_NEAR(test::solid_color(*s.objects[1]).rgb.g, 1, 1e-9);
  scene::SurfaceHit hit;
  ASSERT_TRUE(s.objects[2]->intersect({{2, 5, 10}, {0, -1, 0}, 0}, 1e-9, math::kInfinity, hit));
  EXPECT_NEAR(hit.t, 4.9, 1e-6);
}

TEST(LSystemBlock, Errors) {
  EXPECT_NE(
      error_of(R"(lsystem { axiom "F" rule "F" "FF" iterations 30 max_length 1000 })").find("max_length"),
      std::string::npos);
  EXPECT_NE(error_of(R"(lsystem { axiom "F]" })").find("without a matching"), std::string::npos);
  EXPECT_NE(error_of(R"(lsystem { axiom "A(x" })").find("missing ')'"), std::string::npos);
  EXPECT_NE(error_of(R"(lsystem { axiom "A" })").find("draws nothing"), std::string::npos);
  EXPECT_NE(error_of(R"(lsystem { axiom "F" interpret "LL" "+" })").find("one-character"), std::string::npos);
  EXPECT_NE(error_of("lsystem { axiom \"F\" rule \"A(x) : y > 1\" \"F\" }").find("unknown name 'y'"),
            std::string::npos);
  EXPECT_NE(error_of(R"(lsystem { axiom "F" leaf { } })").find("holds an object"), std::string::npos);
  EXPECT_NE(error_of(R"(lsystem { axiom "F" rule "F" "FF" iterations 30 max_length 1000 })")
                .find("test.pov:1:1: error"),
            std::string::npos);
}

TEST(TerrainBlock, DiamondSquareExportsWhatTheHeightFieldUses) {
  const auto file =
      std::filesystem::temp_directory_path() / ("snell_terrain_" + std::to_string(getpid()) + ".png");
  const auto s = parse("height_field { diamond_square { size 33 roughness 0.6 seed 7 export \"" +
                       file.string() + "\" } }");
  const io::Image image = io::read_image(file);
  std::filesystem::remove(file);
  ASSERT_EQ(image.width, 33);
  ASSERT_EQ(image.height, 33);
  // Normalised heights: a vertical ray down onto sample (i, k) = (5, 9) meets the surface at the height the
  // file holds in its row 33 - 1 - 9 (rows run top to bottom), to 16-bit precision.
  scene::SurfaceHit hit;
  ASSERT_TRUE(s.objects[0]->intersect({{5 / 32.0, 5, 9 / 32.0}, {0, -1, 0}, 0}, 1e-9, math::kInfinity, hit));
  EXPECT_NEAR(5 - hit.t, image.at(5, 23).r, 2e-5);
  double lo = 1, hi = 0;
  for (int y = 0; y < 33; ++y)
    for (int x = 0; x < 33; ++x) lo = std::min(lo, image.at(x, y).r), hi = std::max(hi, image.at(x, y).r);
  EXPECT_EQ(lo, 0);
  EXPECT_EQ(hi, 1);
}

TEST(TerrainBlock, NoiseTerrainsAndErrors) {
  EXPECT_EQ(error_of("height_field { fbm { size 65 octaves 5 frequency 3 seed 2 } smooth }"), "");
  EXPECT_EQ(error_of("height_field { ridged { size 65 offset 1 gain 2 } }"), "");
  EXPECT_EQ(error_of("height_field { midpoint { size 129 roughness 0.7 } }"), "");
  EXPECT_NE(error_of("height_field { diamond_square { size 100 } }").find("2^n + 1"), std::string::npos);
  EXPECT_NE(error_of("height_field { diamond_square { roughness 2 } }").find("[0, 1]"), std::string::npos);
  EXPECT_NE(error_of("height_field { diamond_square { octaves 2 } }").find("unexpected 'octaves'"),
            std::string::npos);
}

}  // namespace
}  // namespace snell::sdl
