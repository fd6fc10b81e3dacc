// Faults inside scenes (issue 12): each is a located warning or error, never a crash, a hang or a NaN
// pixel. Warnings and errors follow POV-Ray 3.7 where it has one (its parser.cpp and
// parser_expressions.cpp messages are cited per test); the images are EXR, so a NaN would survive.
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <algorithm>

#include "fault_scene.hpp"

namespace snell::test {
namespace {

float brightest(const io::Image& image) {
  return image.rgb.empty() ? 0.0f : *std::max_element(image.rgb.begin(), image.rgb.end());
}

// POV-Ray: "Illegal Value: Scale X by 0.0. Changed to 1.0." (a warning per component).
TEST(SceneFaults, ZeroScaleWarnsAndUsesOne) {
  const FaultRun run = render_fault_scene("zero_scale", "sphere { 0, 1 pigment { rgb 1 } scale 0 }\n");
  expect_warning_and_finite_image(run, "zero_scale.pov:3:39:", "scale component is zero; using 1");
  EXPECT_GT(run.image.at(20, 15).r, 0.1) << "the sphere keeps its size 1 and covers the middle";
}

TEST(SceneFaults, ZeroScaleComponentWarnsAndUsesOne) {
  const FaultRun run =
      render_fault_scene("zero_scale_y", "sphere { 0, 1 pigment { rgb 1 } scale <1, 0, 1> }\n");
  expect_warning_and_finite_image(run, "zero_scale_y.pov:3:39:", "scale component is zero");
  EXPECT_GT(run.image.at(20, 15).r, 0.1);
}

// POV-Ray stops at the expression: "sqrt of negative number".
TEST(SceneFaults, NanScaleIsAnError) {
  const FaultRun run =
      render_fault_scene("nan_scale", "sphere { 0, 1 pigment { rgb 1 } scale <1, sqrt(-1), 1> }\n");
  expect_scene_error(run, "nan_scale.pov:3:43:", "sqrt");
}

TEST(SceneFaults, InfiniteScaleIsAnError) {
  const FaultRun run =
      render_fault_scene("inf_scale", "sphere { 0, 1 pigment { rgb 1 } scale <1, 1e200 * 1e200, 1> }\n");
  expect_scene_error(run, "inf_scale.pov:3:39:", "scale amount is not a finite number");
}

// POV-Ray: "Degenerate triangle. Please remove." (a warning; the triangle is dropped).
TEST(SceneFaults, DegenerateTriangleWarns) {
  const FaultRun run = render_fault_scene("degenerate_triangle",
                                          "triangle { <0, 0, 0>, <1, 1, 1>, <2, 2, 2> pigment { rgb 1 } }\n");
  expect_warning_and_finite_image(run, "degenerate_triangle.pov:3:1:", "degenerate triangle");
  EXPECT_EQ(brightest(run.image), 0.0f) << "nothing to see: a line has no area";
}

// POV-Ray skips a mesh's degenerate faces silently; snell says how many, once per mesh.
TEST(SceneFaults, DegenerateMeshFacesWarnOncePerMesh) {
  const FaultRun run = render_fault_scene("degenerate_mesh",
                                          "mesh {\n"
                                          "  triangle { <0, 0, 0>, <1, 1, 1>, <2, 2, 2> }\n"
                                          "  triangle { <0, 0, 0>, <0, 0, 0>, <0, 0, 0> }\n"
                                          "  triangle { <-1, -1, 0>, <1, -1, 0>, <0, 1, 0> }\n"
                                          "  pigment { rgb 1 }\n"
                                          "}\n");
  expect_warning_and_finite_image(run, "degenerate_mesh.pov:3:1:", "2 triangles have no area");
  EXPECT_GT(run.image.at(20, 15).r, 0.1) << "the proper triangle still renders";
}

TEST(SceneFaults, DegenerateMesh2FacesWarn) {
  const FaultRun run =
      render_fault_scene("degenerate_mesh2",
                         "mesh2 { vertex_vectors { 4, <-1, -1, 0>, <1, -1, 0>, <0, 1, 0>, <3, 3, 0> }\n"
                         "  face_indices { 2, <0, 1, 2>, <0, 0, 3> } pigment { rgb 1 } }\n");
  expect_warning_and_finite_image(run, "degenerate_mesh2.pov:3:1:", "1 triangle has no area");
}

// POV-Ray renders a zero-radius sphere as nothing, without a message.
TEST(SceneFaults, ZeroRadiusSphereRendersNothing) {
  const FaultRun run = render_fault_scene("zero_sphere", "sphere { 0, 0 pigment { rgb 1 } }\n");
  EXPECT_EQ(run.outcome.code, 0) << run.outcome.output;
  ASSERT_TRUE(run.written);
  EXPECT_TRUE(all_finite(run.image));
  EXPECT_EQ(brightest(run.image), 0.0f);
}

// POV-Ray: "Illegal matrix column: Scale by 0.0. Changed to 1.0." (Parse_Matrix).
TEST(SceneFaults, MatrixWithAZeroColumnWarnsAndUsesOne) {
  const FaultRun run = render_fault_scene(
      "zero_column_matrix", "box { -1, 1 pigment { rgb 1 } matrix <1, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0> }\n");
  expect_warning_and_finite_image(run, "zero_column_matrix.pov:3:38:", "matrix column 2 is zero");
  EXPECT_GT(run.image.at(20, 15).r, 0.1) << "the box stays a unit box";
}

TEST(SceneFaults, MatrixStillSingularIsAnError) {
  const FaultRun run = render_fault_scene(
      "singular_matrix", "box { -1, 1 pigment { rgb 1 } matrix <1, 1, 0, 1, 1, 0, 0, 0, 1, 0, 0, 0> }\n");
  expect_scene_error(run, "singular_matrix.pov:3:38:", "singular matrix");
}

// POV-Ray: "Cannot open file" errors for each.
TEST(SceneFaults, MissingImageMapFileIsLocated) {
  const FaultRun run =
      render_fault_scene("missing_image", "plane { z, 1 pigment { image_map { png \"no_such.png\" } } }\n");
  expect_scene_error(run, "missing_image.pov:3:40:", "cannot find file \"no_such.png\"");
}

TEST(SceneFaults, MissingHeightFieldFileIsLocated) {
  const FaultRun run = render_fault_scene("missing_hf", "height_field { png \"no_such_hf.png\" }\n");
  expect_scene_error(run, "missing_hf.pov:3:20:", "cannot find height_field image \"no_such_hf.png\"");
}

TEST(SceneFaults, MissingFontFileIsLocated) {
  const FaultRun run = render_fault_scene(
      "missing_font", "text { ttf \"no_such_font.ttf\" \"abc\" 1, 0 pigment { rgb 1 } }\n");
  expect_scene_error(run, "missing_font.pov:3:12:", "cannot find the font \"no_such_font.ttf\"");
}

TEST(SceneFaults, MissingIncludedMeshFileIsLocated) {
  // A mesh comes from a file only through #include (snell has no mesh importer yet).
  const FaultRun run = render_fault_scene("missing_mesh", "#include \"no_such_mesh.inc\"\nobject { Mesh }\n");
  expect_scene_error(run, "missing_mesh.pov:3:1:", "no_such_mesh.inc");
}

// POV-Ray loops forever; snell stops the loop at --max-loop iterations.
TEST(SceneFaults, EndlessWhileStopsAtMaxLoop) {
  const FaultRun run = render_fault_scene("endless_while",
                                          "#declare I = 0;\n"
                                          "#while (I < 10)\n"
                                          "#end\n",
                                          "--max-loop 1000");
  expect_scene_error(run, "endless_while.pov:4:1:", "more than 1000 iterations");
}

// POV-Ray allocates the claimed count up front and fails with std::bad_alloc.
TEST(SceneFaults, BillionClaimedMeshFacesIsAnError) {
  const FaultRun run = render_fault_scene("billion_faces",
                                          "mesh2 { vertex_vectors { 3, <0, 0, 0>, <1, 0, 0>, <0, 1, 0> } "
                                          "face_indices { 1000000000, <0, 1, 2> } }\n");
  expect_scene_error(run,
                     "billion_faces.pov:3:78:", "face_indices must be a whole number from 0 to 50000000");
}

TEST(SceneFaults, LargeClaimedCountIsNotAllocatedUpFront) {
  // 40 million claimed faces (480 MiB as index triples) but one given: an error, without the allocation.
  const FaultRun run = render_fault_scene("claimed_faces",
                                          "mesh2 { vertex_vectors { 3, <0, 0, 0>, <1, 0, 0>, <0, 1, 0> } "
                                          "face_indices { 40000000, <0, 1, 2> } }\n");
  expect_scene_error(run, "claimed_faces.pov:3:100:", "face_indices holds 1 items, its count says 40000000");
  rusage usage{};
  getrusage(RUSAGE_CHILDREN, &usage);
  EXPECT_LT(usage.ru_maxrss, 200 * 1024) << "peak resident KiB of the snell process";
}

// POV-Ray renders these with no message; snell's isosurface treats NaN as "outside" and the renderer's
// guard keeps anything else from the image.
TEST(SceneFaults, IsosurfaceReturningNanRendersFinite) {
  const FaultRun run = render_fault_scene("nan_isosurface",
                                          "isosurface { function { sqrt(x) + y * y + z * z - 1 } "
                                          "contained_by { box { -2, 2 } } pigment { rgb 1 } }\n");
  EXPECT_EQ(run.outcome.code, 0) << run.outcome.output;
  ASSERT_TRUE(run.written) << run.outcome.output;
  EXPECT_TRUE(all_finite(run.image));
}

TEST(SceneFaults, IsosurfaceNanEverywhereRendersFinite) {
  const FaultRun run = render_fault_scene(
      "nan_everywhere",
      "isosurface { function { log(-1 - x * x) } contained_by { box { -2, 2 } } pigment { rgb 1 } }\n");
  EXPECT_EQ(run.outcome.code, 0) << run.outcome.output;
  ASSERT_TRUE(run.written) << run.outcome.output;
  EXPECT_TRUE(all_finite(run.image));
}

TEST(SceneFaults, InfiniteLightIsCaughtByTheRenderersGuard) {
  const FaultRun run = render_fault_scene(
      "infinite_light", "light_source { <0, 0, -5> rgb 1e200 * 1e200 }\nsphere { 0, 1 pigment { rgb 1 } }\n");
  EXPECT_EQ(run.outcome.code, 0) << run.outcome.output;
  ASSERT_TRUE(run.written) << run.outcome.output;
  EXPECT_TRUE(all_finite(run.image));
  EXPECT_NE(run.outcome.output.find("samples were NaN or infinite and were rendered black"),
            std::string::npos)
      << run.outcome.output;
}

// Negative sizes: POV-Ray squares a sphere's radius; snell refuses radii that have no meaning.
TEST(SceneFaults, NegativeSphereRadiusRendersLikeItsSize) {
  const FaultRun run = render_fault_scene("negative_sphere", "sphere { 0, -1 pigment { rgb 1 } }\n");
  EXPECT_EQ(run.outcome.code, 0) << run.outcome.output;
  ASSERT_TRUE(run.written);
  EXPECT_TRUE(all_finite(run.image));
  EXPECT_GT(run.image.at(20, 15).r, 0.1);
}

TEST(SceneFaults, NegativeCylinderRadiusIsAnError) {
  const FaultRun run = render_fault_scene("negative_cylinder", "cylinder { -y, y, -1 pigment { rgb 1 } }\n");
  expect_scene_error(run, "negative_cylinder.pov:3:1:", "radius must be positive");
}

TEST(SceneFaults, NegativeTorusRadiusIsAnError) {
  const FaultRun run = render_fault_scene("negative_torus", "torus { -1, 0.2 pigment { rgb 1 } }\n");
  expect_scene_error(run, "negative_torus.pov:3:1:", "major radius must not be negative");
}

}  // namespace
}  // namespace snell::test
