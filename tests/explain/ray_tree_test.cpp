// The ray tree against optics from outside the code: ../shared/reference-values.md section 3 (Snell's law
// in vector form, the critical angle of glass 41.810315 degrees), and against the scene's own layout.
#include "snell/render/explain/ray_tree.hpp"

#include <fmt/core.h>
#include <gtest/gtest.h>

#include <cmath>

#include "explain_scenes.hpp"
#include "snell/render/explain/explain_pixel.hpp"
#include "snell/render/whitted.hpp"

namespace snell::render::explain {
namespace {

using math::Vec3;

/// The tree of one ray traced through `scene` as the camera ray.
std::unique_ptr<RayNode> trace_tree(const scene::Scene& scene, const math::Ray& ray) {
  const auto accel = accel::make_accelerator("none", scene);
  WhittedIntegrator integrator(scene, *accel);
  RayTreeRecorder recorder(scene);
  TraceContext context;
  context.observer = &recorder;
  integrator.trace_camera_ray(ray, context);
  return recorder.take_root();
}

const RayNode* child(const RayNode& node, scene::RayKind kind,
                     RayEnd end_not = RayEnd::total_internal_reflection) {
  for (const RayNode& c : node.children)
    if (c.kind == kind && c.end != end_not) return &c;
  return nullptr;
}

void expect_near(const Vec3& a, const Vec3& b, double tolerance) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(RayTreeTest, GlassSphereAt45DegreesHasReferenceReflectedAndRefractedDirections) {
  const scene::Scene scene = test::parse(test::kGlassSphere);
  // A ray along +z at height sin 45 deg meets the unit sphere at 45 deg incidence: n = (s, 0, -c).
  const double s = std::sqrt(0.5), c = std::sqrt(0.5);
  const auto root = trace_tree(scene, {{s, 0, -5}, {0, 0, 1}});
  ASSERT_TRUE(root);
  ASSERT_TRUE(root->hit);
  EXPECT_TRUE(root->entering);
  EXPECT_EQ(root->surface.object->name, "Glass");
  // Reference values (section 3): i = (sqrt 1/2, -sqrt 1/2, 0), n = (0, 1, 0), eta = 1/1.5 gives
  // t = (0.4714045208, -0.8819171037, 0): 0.4714045208 along the incident ray's tangent, 0.8819171037 along
  // -n. Here the tangent is (c, 0, s) and -n = (-s, 0, c).
  const Vec3 tangent(c, 0, s), inward(-s, 0, c);
  const Vec3 refracted = 0.4714045208 * tangent + 0.8819171037 * inward;
  // Reflection r = i - 2(i.n)n = (0,0,1) + 2c(s,0,-c) = (1, 0, 0).
  const Vec3 reflected(1, 0, 0);
  const RayNode* t = child(*root, scene::RayKind::refraction);
  const RayNode* r = child(*root, scene::RayKind::reflection);
  ASSERT_TRUE(t);
  ASSERT_TRUE(r);
  expect_near(t->ray.direction, refracted, 1e-9);
  expect_near(r->ray.direction, reflected, 1e-9);
  EXPECT_EQ(t->level, 2);
  // The refracted ray leaves the sphere at its far side.
  ASSERT_TRUE(t->hit);
  EXPECT_FALSE(t->entering);
  // Its terms name the transmitted and reflected light with the finish's weights.
  bool transmitted = false, reflected_term = false;
  for (const TermRecord& term : root->terms) {
    if (term.term == RayTerm::transmitted) {
      transmitted = true;
      EXPECT_NEAR(term.weight.r, 0.9, 1e-12);
    }
    if (term.term == RayTerm::reflected) {
      reflected_term = true;
      EXPECT_NEAR(term.weight.r, 0.1, 1e-12);
    }
  }
  EXPECT_TRUE(transmitted);
  EXPECT_TRUE(reflected_term);
}

/// A glass prism: entered head-on through z = 0, left through a face tilted by `degrees` from it.
scene::Scene prism(double degrees) {
  const double a = degrees * 3.14159265358979323846 / 180;
  return test::parse(
      fmt::format("#version 3.7; global_settings {{ assumed_gamma 1 max_trace_level 6 }}\n"
                  "camera {{ location <0, 0, -5> look_at <0, 0, 0> }}\n"
                  "light_source {{ <3, 5, -4> color rgb 1 }}\n"
                  "#declare Prism = intersection {{ plane {{ -z, 0 }} plane {{ <{:.17g}, 0, {:.17g}>, 1 }}\n"
                  "  plane {{ y, 1 }} plane {{ -y, 1 }} plane {{ x, 3 }} plane {{ -x, 3 }}\n"
                  "  pigment {{ rgbf <1, 1, 1, 1> }} interior {{ ior 1.5 }} }}\n"
                  "object {{ Prism }}\nbackground {{ rgb <0.1, 0.2, 0.4> }}\n",
                  -std::sin(a), std::cos(a)));
}

TEST(RayTreeTest, TotalInternalReflectionLeafBeyondTheCriticalAngle) {
  // Glass to air at 45 deg > 41.810315 deg (the critical angle, reference values section 3): TIR.
  const auto root = trace_tree(prism(45), {{0, 0, -5}, {0, 0, 1}});
  ASSERT_TRUE(root && root->hit);
  const RayNode* inside = child(*root, scene::RayKind::refraction);
  ASSERT_TRUE(inside);
  expect_near(inside->ray.direction, {0, 0, 1}, 1e-12);  // normal incidence goes straight on
  ASSERT_TRUE(inside->hit);
  EXPECT_FALSE(inside->entering);
  const RayNode* leaf = nullptr;
  for (const RayNode& c : inside->children)
    if (c.end == RayEnd::total_internal_reflection) leaf = &c;
  ASSERT_TRUE(leaf) << "no total internal reflection leaf";
  EXPECT_EQ(leaf->kind, scene::RayKind::refraction);
  EXPECT_TRUE(leaf->children.empty());
  // The reflected ray takes its place: (0,0,1) mirrored on n = (-s, 0, c) is (1, 0, 0).
  const RayNode* mirrored = child(*inside, scene::RayKind::reflection);
  ASSERT_TRUE(mirrored);
  expect_near(mirrored->ray.direction, {1, 0, 0}, 1e-9);
}

TEST(RayTreeTest, NoTotalInternalReflectionBelowTheCriticalAngle) {
  // At 40 deg < 41.81 deg the ray leaves: sin t = 1.5 sin 40 deg (Snell), so t = 74.6 deg from the normal.
  const auto root = trace_tree(prism(40), {{0, 0, -5}, {0, 0, 1}});
  const RayNode* inside = child(*root, scene::RayKind::refraction);
  ASSERT_TRUE(inside);
  for (const RayNode& c : inside->children) EXPECT_NE(c.end, RayEnd::total_internal_reflection);
  const RayNode* out = child(*inside, scene::RayKind::refraction);
  ASSERT_TRUE(out);
  const double a = 40 * 3.14159265358979323846 / 180;
  const Vec3 n(-std::sin(a), 0, std::cos(a));
  EXPECT_NEAR(dot(out->ray.direction, n), std::cos(std::asin(1.5 * std::sin(a))), 1e-9);
}

TEST(RayTreeTest, MissReportsTheBackground) {
  const scene::Scene scene = test::parse(test::kGlassSphere);
  const auto accel = accel::make_accelerator("none", scene);
  RenderOptions o;
  o.width = 40;
  o.height = 30;
  // The top-left pixel looks above the sphere and the floor.
  const PixelExplanation e = explain_pixel(scene, *accel, o, 0, 0, 0);
  ASSERT_TRUE(e.tree);
  EXPECT_FALSE(e.tree->hit);
  EXPECT_EQ(e.tree->end, RayEnd::miss);
  EXPECT_NEAR(e.tree->result.r, 0.1, 1e-12);
  EXPECT_NEAR(e.tree->result.g, 0.2, 1e-12);
  EXPECT_NEAR(e.tree->result.b, 0.4, 1e-12);
  EXPECT_THROW(explain_pixel(scene, *accel, o, 40, 0, 0), std::invalid_argument);
  EXPECT_THROW(explain_pixel(scene, *accel, o, 0, 0, 1), std::invalid_argument);
}

TEST(RayTreeTest, EachShadowRayNamesItsLightAndItsOccluder) {
  // The floor point under the blocker sees light 1 only through it; light 2, low on the other side, is clear.
  const scene::Scene scene = test::parse(R"(
#version 3.7;
camera { location <0, 5, -5> look_at <0, 0, 0> }
light_source { <0, 10, 0> color rgb 1 }
light_source { <10, 1, 0> color rgb 1 }
#declare Blocker = sphere { <0, 3, 0>, 1 pigment { rgb 1 } }
object { Blocker }
#declare Floor = plane { y, 0 pigment { rgb 1 } }
object { Floor }
)");
  const Vec3 from(0, 5, -5);
  const auto root = trace_tree(scene, {from, normalize(Vec3(0, 0, 0) - from)});
  ASSERT_TRUE(root && root->hit);
  EXPECT_EQ(root->surface.object->name, "Floor");
  int shadows = 0;
  for (const RayNode& c : root->children) {
    if (c.kind != scene::RayKind::shadow) continue;
    ++shadows;
    ASSERT_TRUE(c.light);
    if (c.light_index == 0) {
      EXPECT_EQ(c.end, RayEnd::light_blocked);
      ASSERT_FALSE(c.blockers.empty());
      EXPECT_EQ(c.blockers[0].object->name, "Blocker");
      EXPECT_NEAR(c.blockers[0].distance, 2.0, 1e-6);  // the blocker's underside at y = 2
    } else {
      EXPECT_EQ(c.light_index, 1);
      EXPECT_EQ(c.end, RayEnd::light_reached);
      EXPECT_TRUE(c.blockers.empty());
    }
  }
  EXPECT_EQ(shadows, 2);
}

TEST(RayTreeTest, DepthLimitEndsTheRecursion) {
  // Two facing mirrors: the tree stops at max_trace_level 3 with a depth_limit leaf.
  const scene::Scene scene = test::parse(R"(
#version 3.7;
global_settings { max_trace_level 3 }
camera { location <0, 0, 0> look_at <0, 0, 1> }
plane { z, 2 pigment { rgb 0 } finish { reflection 1 ambient 0 diffuse 0 } }
plane { -z, 2 pigment { rgb 0 } finish { reflection 1 ambient 0 diffuse 0 } }
)");
  const auto root = trace_tree(scene, {{0, 0, 0}, {0, 0, 1}});
  const RayNode* n = root.get();
  int depth = 1;
  while (const RayNode* next = child(*n, scene::RayKind::reflection)) {
    n = next;
    ++depth;
  }
  EXPECT_EQ(depth, 4);
  EXPECT_EQ(n->end, RayEnd::depth_limit);
  EXPECT_EQ(n->level, 4);
}

}  // namespace
}  // namespace snell::render::explain
