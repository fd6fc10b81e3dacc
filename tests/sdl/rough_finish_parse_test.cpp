// snell's rough-surface finish extension (docs/language.md, "Glossy reflection and frosted glass"):
// `reflection { ... blur A samples N }` and `transmission { blur A samples N }`, and their errors.
#include <gtest/gtest.h>

#include "sdl_test_util.hpp"

namespace snell::sdl {
namespace {

TEST(SdlRoughFinish, ReflectionBlurAndSamples) {
  const auto scene = test::parse(R"(
    sphere { 0, 1 finish { reflection { 0.1, 0.8 fresnel blur 0.05 samples 12 metallic } roughness 0.01 } }
    sphere { 0, 1 finish { reflection { 0.5 } } }
  )");
  const auto& f = scene.objects[0]->texture->finish;
  EXPECT_EQ(f.reflection_blur, 0.05);
  EXPECT_EQ(f.reflection_samples, 12);
  EXPECT_EQ(f.reflection_max, math::Color(0.8));
  EXPECT_EQ(f.reflection_metallic, 1);
  // POV-Ray's `roughness` stays the specular highlight's.
  EXPECT_EQ(f.roughness, 0.01);
  const auto& g = scene.objects[1]->texture->finish;
  EXPECT_EQ(g.reflection_blur, 0);
  EXPECT_EQ(g.reflection_samples, 0);
}

TEST(SdlRoughFinish, TransmissionBlock) {
  const auto scene = test::parse(R"(
    #declare Frost = finish { transmission { blur 0.2 samples 4 } }
    sphere { 0, 1 finish { Frost diffuse 0.3 } }
  )");
  const auto& f = scene.objects[0]->texture->finish;
  EXPECT_EQ(f.transmission_blur, 0.2);
  EXPECT_EQ(f.transmission_samples, 4);
  EXPECT_EQ(f.diffuse, 0.3);
}

TEST(SdlRoughFinish, BadValuesAreErrorsWithTheirPlace) {
  // The error points at the value.
  EXPECT_NE(test::error_of("sphere { 0, 1 finish { reflection { 0.5 blur -0.1 } } }")
                .find("test.pov:1:46: error: blur must be from 0 (a mirror) to 1"),
            std::string::npos);
  EXPECT_NE(test::error_of("sphere { 0, 1 finish { reflection { 0.5 samples 0 } } }").find("samples must be"),
            std::string::npos);
  EXPECT_NE(test::error_of("sphere { 0, 1 finish { transmission { ior 1.5 } } }")
                .find("1:39: error: unexpected 'ior' in transmission"),
            std::string::npos);
}

}  // namespace
}  // namespace snell::sdl
