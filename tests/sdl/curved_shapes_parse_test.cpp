// Parsing ovus, lemon and parametric (POV-Ray 3.7 reference "Ovus", "Parametric"; 3.8 "Lemon"), and the
// u, v aliases of a function's x, y that parametric's functions use (POV-Ray's fncode.cpp).
#include <gtest/gtest.h>

#include <cmath>

#include "sdl_test_util.hpp"
#include "snell/math/constants.hpp"

namespace snell::sdl {
namespace {

using test::error_of;
using test::parse;

double first_t(const scene::Scene& s, const math::Ray& ray) {
  scene::SurfaceHit hit;
  if (!s.objects.at(0)->intersect(ray, 1e-9, math::kInfinity, hit)) return -1;
  return hit.t;
}

TEST(CurvedShapesParse, OvusWithModifiers) {
  const auto s = parse("ovus { 1, 0.5 translate 5 * x }");
  ASSERT_EQ(s.objects.size(), 1u);
  EXPECT_NEAR(first_t(s, {{5, 5, 0}, {0, -1, 0}, 0}), 3.5, 1e-9);  // the top sphere's top, y = 1.5
}

TEST(CurvedShapesParse, LemonOpenAndTooThin) {
  const auto s = parse("lemon { <0, 0, 0>, 0.5, <0, 2, 0>, 0.5, 2 open }");
  EXPECT_LT(first_t(s, {{0, -5, 0}, {0, 1, 0}, 0}), 0);  // open ends: straight through
  std::vector<std::string> messages;
  parse("lemon { 0, 0, y, 0, 0.1 }", &messages);
  bool warned = false;
  for (const std::string& m : messages) warned |= m.find("inner radius is too small") != std::string::npos;
  EXPECT_TRUE(warned);
}

TEST(CurvedShapesParse, ParametricSphereInUAndV) {
  const auto s = parse(R"(
    parametric {
      function { cos(v) * cos(u) } function { sin(v) } function { cos(v) * sin(u) }
      <0, -pi / 2>, <2 * pi, pi / 2>
      contained_by { sphere { 0, 1.1 } } max_gradient 2 accuracy 0.0001 precompute 12, x, y, z
    })");
  EXPECT_NEAR(first_t(s, {{0, 0.3, -5}, {0, 0, 1}, 0}), 5 - std::sqrt(1 - 0.09), 1e-8);
}

TEST(CurvedShapesParse, Errors) {
  const auto has = [](const std::string& text, const std::string& part) {
    const std::string e = error_of(text);
    EXPECT_NE(e.find(part), std::string::npos) << "got: " << e;
  };
  has("ovus { 0, 1 }", "test.pov:1:1: error: ovus: both radii must be positive");
  has("ovus { 1, 1 radius 1 }", "connecting radius");
  has("lemon { 0, 1, 0, 1, 2 }", "test.pov:1:1: error: lemon: base and cap coincide");
  has("parametric { function { u } function { v } <0, 0>, <1, 1> }", "parametric needs three functions");
  has("parametric { function { u } function { u } function { 0 } <0, 0>, <1, 1> }",
      "the surface has no area");
}

}  // namespace
}  // namespace snell::sdl
