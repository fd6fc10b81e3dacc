#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>
#include <vector>

#include "shape_checks.hpp"
#include "snell/geometry/polygon.hpp"
#include "snell/geometry/prism.hpp"
#include "snell/geometry/text_outline.hpp"

using namespace snell::geometry;
using snell::geometry::shape_checks::expect_near;
using snell::math::kInfinity;

TEST(PolygonTest, SquareWithHole) {
  // Outer square, then an inner one: the even-odd rule makes it a hole (POV-Ray reference, "Polygon").
  const std::vector<Vec3> p{{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0}, {0, 0, 0},
                            {1, 1, 0}, {3, 1, 0}, {3, 3, 0}, {1, 3, 0}, {1, 1, 0}};
  const Polygon polygon(p);
  LocalHit hit;
  ASSERT_TRUE(polygon.intersect({{0.5, 0.5, -2}, {0, 0, 0.5}, 0}, 0, kInfinity, hit));
  EXPECT_NEAR(hit.t, 4, 1e-12);
  EXPECT_NEAR(std::fabs(normalize(hit.normal).z), 1, 1e-12);
  EXPECT_FALSE(polygon.intersect({{2, 2, -2}, {0, 0, 1}, 0}, 0, kInfinity, hit));      // the hole
  EXPECT_FALSE(polygon.intersect({{5, 2, -2}, {0, 0, 1}, 0}, 0, kInfinity, hit));      // outside
  EXPECT_FALSE(polygon.intersect({{0.5, 0.5, -2}, {1, 0, 0}, 0}, 0, kInfinity, hit));  // parallel
  EXPECT_FALSE(polygon.inside({0.5, 0.5, 0}));
}

TEST(PolygonTest, TiltedTriangle) {
  const std::vector<Vec3> p{{0, 0, 0}, {1, 1, 0}, {0, 1, 1}};
  const Polygon polygon(p);
  LocalHit hit;
  // The plane x - y + z = 0; the centroid (1/3, 2/3, 1/3) is inside.
  ASSERT_TRUE(polygon.intersect({{1.0 / 3, 2.0 / 3 + 3, 1.0 / 3}, {0, -1, 0}, 0}, 0, kInfinity, hit));
  EXPECT_NEAR(hit.t, 3, 1e-12);
  expect_near(normalize(hit.normal) * (hit.normal.x > 0 ? 1.0 : -1.0), Vec3(1, -1, 1) / std::sqrt(3.0),
              1e-12);
}

TEST(PolygonTest, UnclosedPolygonIsClosed) {
  // A square with a notch: the missing closing edge (1,1)-(0,0) bounds the notch's lower side.
  const std::vector<Vec3> p{{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {1, 1, 0}};
  LocalHit hit;
  EXPECT_TRUE(Polygon(p).intersect({{1.5, 1, -1}, {0, 0, 1}, 0}, 0, kInfinity, hit));
  // In the notch: without the closing edge the even-odd count would call this point inside.
  EXPECT_FALSE(Polygon(p).intersect({{0.3, 0.6, -1}, {0, 0, 1}, 0}, 0, kInfinity, hit));
}

TEST(PolygonTest, CollinearPointsAreRejected) {
  const std::vector<Vec3> p{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  EXPECT_THROW(Polygon{p}, std::invalid_argument);
}

namespace {
const std::filesystem::path kFonts = POVRAY_INCLUDE_DIR;
}

TEST(TextTest, GlyphLayoutFollowsPovRay) {
  // Reference extents measured with POV-Ray 3.7: min_extent / max_extent of
  // text { ttf "timrom.ttf" "POV-Ray" 1, 0 } are <0, -0.212, 0> and <3.796, 0.696, 1>.
  const Outline i = text_outline(kFonts / "timrom.ttf", "I", {0, 0});
  EXPECT_NEAR(i.lo().u, 0, 1e-9);
  const Outline pov = text_outline(kFonts / "timrom.ttf", "POV-Ray", {0, 0});
  EXPECT_NEAR(pov.lo().u, 0, 1e-9);
  EXPECT_NEAR(pov.hi().u, 3.796, 2e-3);
  EXPECT_NEAR(pov.lo().v, -0.212, 2e-3);
  EXPECT_NEAR(pov.hi().v, 0.696, 2e-3);
  // An offset adds to every advance.
  const Outline spaced = text_outline(kFonts / "timrom.ttf", "POV-Ray", {0.1, 0});
  EXPECT_NEAR(spaced.hi().u - pov.hi().u, 0.6, 1e-9);
}

TEST(TextTest, ExtrudedGlyphs) {
  const Prism text(text_outline(kFonts / "timrom.ttf", "I", {0, 0}), 0, 0.5, Sweep::linear, false, true);
  const Bounds3 b = text.bounds();
  EXPECT_NEAR(b.lo.z, 0, 1e-12);
  EXPECT_NEAR(b.hi.z, 0.5, 1e-12);
  // Straight into the middle of the letter I: the front face at z = 0, then the back at z = 0.5.
  const Vec3 middle = b.center();
  HitList hits;
  text.all_hits({{middle.x, middle.y, -2}, {0, 0, 1}, 0}, 0, kInfinity, hits);
  ASSERT_EQ(hits.size(), 2u);
  EXPECT_NEAR(hits[0].t, 2, 1e-12);
  expect_near(hits[0].normal, {0, 0, -1}, 1e-12);
  EXPECT_NEAR(hits[1].t, 2.5, 1e-12);
  EXPECT_TRUE(text.inside({middle.x, middle.y, 0.25}));
  shape_checks::check_random_rays(text, true, 500);
  shape_checks::check_random_rays(
      Prism(text_outline(kFonts / "crystal.ttf", "B&8", {0, 0}), 0, 0.3, Sweep::linear, false, true), true,
      500);
}

TEST(TextTest, MissingFontAndBlankText) {
  EXPECT_THROW(text_outline("/nonexistent/font.ttf", "A", {0, 0}), std::runtime_error);
  EXPECT_THROW(text_outline(kFonts / "timrom.ttf", "   ", {0, 0}), std::invalid_argument);
}
