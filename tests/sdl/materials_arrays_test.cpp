// material {}, layered textures, #default, arrays, #for and seed/rand as parsed from scene text
// (POV-Ray 3.7 reference: "Material", "Layered Textures", "The #default Directive", "Array Identifiers",
// "The #for Directive", "Float Functions").
#include <gtest/gtest.h>

#include "sdl_test_util.hpp"

using namespace snell;

namespace {

/// What `#debug` printed, in order.
std::vector<std::string> debug_of(const std::string& text) {
  std::vector<std::string> messages;
  sdl::test::parse(text, &messages);
  return messages;
}

material::Rgbft stack_color(const scene::Object& o, const math::Vec3& p = {}) {
  return o.texture->pigment_at(p, {0, 1, 0}, {});
}

}  // namespace

TEST(SdlMaterial, MaterialGivesTextureAndInterior) {
  const auto s = sdl::test::parse(R"(
    #declare M = material { texture { pigment { rgb <1, 0, 0> } finish { ambient 0.3 } } interior { ior 1.5 } }
    sphere { 0, 1 material { M } }
    sphere { 0, 1 material { M interior { ior 1.33 } } })");
  ASSERT_EQ(s.objects.size(), 2u);
  EXPECT_EQ(sdl::test::solid_color(*s.objects[0]).rgb.r, 1);
  EXPECT_DOUBLE_EQ(s.objects[0]->texture->finish.ambient.r, 0.3);
  ASSERT_TRUE(s.objects[0]->interior);
  EXPECT_DOUBLE_EQ(s.objects[0]->interior->ior, 1.5);
  EXPECT_DOUBLE_EQ(s.objects[1]->interior->ior, 1.33);
  EXPECT_EQ(sdl::test::solid_color(*s.objects[1]).rgb.r, 1);
}

TEST(SdlMaterial, MaterialTransformMovesItsTexture) {
  const auto s =
      sdl::test::parse("sphere { 0, 1 material { texture { pigment { rgb 1 } } translate <2, 0, 0> } }");
  EXPECT_EQ(s.objects[0]->texture->transform.inverse_point({2, 0, 0}).x, 0);
}

TEST(SdlMaterial, TexturesIncParsesItsMaterials) {
  const auto s = sdl::test::parse("#include \"textures.inc\"\nsphere { 0, 1 material { M_Glass } }");
  ASSERT_TRUE(s.objects[0]->interior);
  EXPECT_DOUBLE_EQ(s.objects[0]->interior->ior, 1.5);  // M_Glass uses I_Glass: ior 1.5
}

TEST(SdlMaterial, UnknownItemIsAnError) {
  EXPECT_NE(sdl::test::error_of("sphere { 0, 1 material { pigment { rgb 1 } } }").find("in material"),
            std::string::npos);
}

TEST(SdlLayers, LaterTextureLiesOnTop) {
  // A half-transmitting red layer over opaque blue: red * 0.5 + blue * 0.5, opaque.
  const auto s = sdl::test::parse(R"(
    sphere { 0, 1 texture { pigment { rgb <0, 0, 1> } } texture { pigment { rgbt <1, 0, 0, 0.5> } } })");
  const auto c = stack_color(*s.objects[0]);
  EXPECT_NEAR(c.rgb.r, 0.5, 1e-12);
  EXPECT_NEAR(c.rgb.g, 0, 1e-12);
  EXPECT_NEAR(c.rgb.b, 0.5, 1e-12);
  EXPECT_NEAR(c.filter + c.transmit, 0, 1e-12);
}

TEST(SdlLayers, FilterTintsTheLayerBelow) {
  // Filter 1 of yellow over white: only what yellow passes (r, g) of the white below shows.
  const auto s = sdl::test::parse(R"(
    #declare T = texture { pigment { rgb 1 } } texture { pigment { rgbf <1, 1, 0, 1> } }
    sphere { 0, 1 texture { T } })");
  const auto c = stack_color(*s.objects[0]);
  EXPECT_NEAR(c.rgb.r, 1, 1e-12);
  EXPECT_NEAR(c.rgb.g, 1, 1e-12);
  EXPECT_NEAR(c.rgb.b, 0, 1e-12);
}

TEST(SdlLayers, PatternLayerShowsLowerLayerWhereClear) {
  // Checker of clear and opaque green over red: red in the clear cells, green in the others.
  const auto s = sdl::test::parse(R"(
    plane { y, 0 texture { pigment { rgb <1, 0, 0> } }
                 texture { pigment { checker rgbt <0, 0, 0, 1>, rgb <0, 1, 0> } } })");
  const auto a = stack_color(*s.objects[0], {0.5, 0.5, 0.5});
  const auto b = stack_color(*s.objects[0], {1.5, 0.5, 0.5});
  EXPECT_NEAR(a.rgb.r, 1, 1e-12);
  EXPECT_NEAR(a.rgb.g, 0, 1e-12);
  EXPECT_NEAR(b.rgb.r, 0, 1e-12);
  EXPECT_NEAR(b.rgb.g, 1, 1e-12);
}

TEST(SdlLayers, ObjectTransformMovesEveryLayer) {
  const auto s = sdl::test::parse(R"(
    plane { y, 0 texture { pigment { rgb 1 } } texture { pigment { rgbt <1, 0, 0, 1> } } translate <3, 0, 0> })");
  const auto& top = *s.objects[0]->texture;
  ASSERT_TRUE(top.below);
  EXPECT_EQ(top.transform.inverse_point({3, 0, 0}).x, 0);
  EXPECT_EQ(top.below->transform.inverse_point({3, 0, 0}).x, 0);
}

TEST(SdlDefault, DefaultFinishAndPigmentApplyToLaterObjects) {
  const auto s = sdl::test::parse(R"(
    sphere { 0, 1 }
    #default { finish { ambient 0.4 } pigment { rgb <0, 1, 0> } }
    sphere { 0, 1 }
    sphere { 0, 1 pigment { rgb 1 } }
    sphere { 0, 1 texture { pigment { rgb 1 } } })");
  ASSERT_EQ(s.objects.size(), 4u);
  EXPECT_DOUBLE_EQ(s.objects[0]->texture->finish.ambient.r, 0.1);  // POV-Ray's own default
  EXPECT_DOUBLE_EQ(s.objects[1]->texture->finish.ambient.r, 0.4);
  EXPECT_EQ(sdl::test::solid_color(*s.objects[1]).rgb.g, 1);
  EXPECT_DOUBLE_EQ(s.objects[2]->texture->finish.ambient.r, 0.4);
  EXPECT_DOUBLE_EQ(s.objects[3]->texture->finish.ambient.r, 0.4);
}

TEST(SdlDefault, OldSpellingWithoutHash) {
  const auto s = sdl::test::parse("default { finish { ambient 0.5 } }\nsphere { 0, 1 }");
  EXPECT_DOUBLE_EQ(s.objects[0]->texture->finish.ambient.r, 0.5);
}

TEST(SdlArrays, InitializerReadAssignAndSizes) {
  const auto out = debug_of(R"(
    #declare A = array[3] { 1, 2, 3 }
    #declare A[1] = A[0] + A[2] * 10;
    #declare B = array[2][3] { { 1, 2, 3 }, { 4, 5, 6 } }
    #debug str(A[1], 0, 0)
    #debug str(B[1][2], 0, 0)
    #debug str(dimension_size(B, 1) * 10 + dimension_size(B, 2), 0, 0)
    #debug str(dimensions(B), 0, 0))");
  ASSERT_EQ(out.size(), 4u);
  EXPECT_EQ(out[0], "31");
  EXPECT_EQ(out[1], "6");
  EXPECT_EQ(out[2], "23");
  EXPECT_EQ(out[3], "2");
}

TEST(SdlArrays, ElementsOfAnyTypeAndCopies) {
  const auto s = sdl::test::parse(R"(
    #declare P = array[2] { pigment { rgb <1, 0, 0> }, pigment { rgb <0, 0, 1> } }
    #declare O = array[1]
    #declare O[0] = sphere { 0, 1 }
    #declare Q = P
    #declare Q[0] = pigment { rgb 1 }
    object { O[0] pigment { P[0] } })");
  ASSERT_EQ(s.objects.size(), 1u);
  EXPECT_EQ(sdl::test::solid_color(*s.objects[0]).rgb.r, 1);
  EXPECT_EQ(sdl::test::solid_color(*s.objects[0]).rgb.g, 0);  // P is unchanged by assigning to its copy Q
}

TEST(SdlArrays, IfdefTellsWhetherAnElementIsSet) {
  const auto out = debug_of(R"(
    #declare A = array[2]
    #declare A[1] = 5;
    #ifdef (A[0]) #debug "0 set" #else #debug "0 unset" #end
    #ifndef (A[1]) #debug "1 unset" #else #debug "1 set" #end)");
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0], "0 unset");
  EXPECT_EQ(out[1], "1 set");
}

TEST(SdlArrays, Errors) {
  EXPECT_NE(sdl::test::error_of("#declare A = array[2]\n#declare X = A[2];").find("out of range"),
            std::string::npos);
  EXPECT_NE(sdl::test::error_of("#declare A = array[2]\n#declare X = A[1];").find("before it was set"),
            std::string::npos);
  EXPECT_NE(sdl::test::error_of("#declare A = array[2] { 1, 2, 3 }").find("more than 2"), std::string::npos);
  EXPECT_NE(sdl::test::error_of("#declare A = array[0]").find("at least 1"), std::string::npos);
}

TEST(SdlFor, CountsUpDownAndBySteps) {
  const auto out = debug_of(R"(
    #declare S = "";
    #for (I, 1, 3) #declare S = concat(S, str(I, 0, 0)); #end
    #for (I, 10, 0, -5) #declare S = concat(S, ",", str(I, 0, 0)); #end
    #for (I, 0, 1, 0.25) #declare S = concat(S, ";", str(I, 0, 2)); #end
    #for (I, 5, 1) #declare S = concat(S, "never"); #end
    #debug S)");
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0], "123,10,5,0;0.00;0.25;0.50;0.75;1.00");
}

TEST(SdlFor, ZeroStepIsAnError) {
  EXPECT_NE(sdl::test::error_of("#for (I, 0, 1, 0) #end").find("step is zero"), std::string::npos);
}

TEST(SdlRandom, SameSeedSameSequenceInUnitInterval) {
  const auto out = debug_of(R"(
    #declare R1 = seed(42);
    #declare R2 = seed(42);
    #declare R3 = seed(7);
    #declare Same = 1;
    #declare Differs = 0;
    #declare InRange = 1;
    #for (I, 1, 100)
      #declare A = rand(R1);
      #declare B = rand(R2);
      #declare C = rand(R3);
      #declare Same = Same & (A = B);
      #declare Differs = Differs | (A != C);
      #declare InRange = InRange & A >= 0 & A < 1;
    #end
    #debug str(Same * 100 + Differs * 10 + InRange, 0, 0))");
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0], "111");
}

// Values printed by POV-Ray 3.7.0 itself (`povray` on Debian 12) for the same scene with
// #debug str(rand(S), 0, 12): snell must draw the very same stream.
TEST(SdlRandom, MatchesPovRaySequence) {
  const auto out = debug_of(R"(
    #declare S = seed(0);
    #debug str(rand(S), 0, 12) #debug str(rand(S), 0, 12) #debug str(rand(S), 0, 12)
    #declare T = seed(12345);
    #debug str(rand(T), 0, 12)
    #declare U = seed(-7.9);
    #debug str(rand(U), 0, 12))");
  ASSERT_EQ(out.size(), 5u);
  EXPECT_EQ(out[0], "0.000002874294");
  EXPECT_EQ(out[1], "0.466563684509");
  EXPECT_EQ(out[2], "0.249070228834");
  EXPECT_EQ(out[3], "0.466563684509");  // seed(0)'s first step leaves the state at 12345
  EXPECT_EQ(out[4], "0.046072868175");  // seed truncates toward zero: -7
}

TEST(SdlRandom, RandNeedsASeededStream) {
  EXPECT_NE(sdl::test::error_of("#declare X = rand(3);").find("seed"), std::string::npos);
}
