// --max-memory (issue 12): a scene whose big arrays would pass the limit stops with an error that names
// the consumer and its place in the scene; within the limit it renders as before.
#include <gtest/gtest.h>

#include "fault_scene.hpp"

namespace snell::test {
namespace {

// 100 000 vertices take 100 000 x 24 bytes = 2.3 MiB, past a 1 MiB limit.
const std::string kBigMesh2 =
    "mesh2 { vertex_vectors { 100000, <0, 0, 0>, <1, 0, 0>, <0, 1, 0> } face_indices { 1, <0, 1, 2> } }\n";

TEST(MemoryLimit, Mesh2PastTheLimitNamesTheListAndItsPlace) {
  const FaultRun run = render_fault_scene("memory_mesh2", kBigMesh2, "--max-memory 1M");
  expect_scene_error(run, "memory_mesh2.pov:3:26:", "mesh2 vertex_vectors needs 2.3 MiB");
  EXPECT_NE(run.outcome.output.find("1.0 MiB memory limit"), std::string::npos) << run.outcome.output;
}

TEST(MemoryLimit, ArrayPastTheLimitIsAnError) {
  const FaultRun run =
      render_fault_scene("memory_array", "#declare A = array[1000000];\n", "--max-memory=16M");
  expect_scene_error(run, "memory_array.pov:3:19:", "array needs");
}

TEST(MemoryLimit, ArraysGiveTheirMemoryBack) {
  // Each array takes about 3.5 of the 16 MiB (a language value is some 700 bytes), and each is given back
  // when the next replaces it: 20 of them held at once would need 70 MiB.
  const FaultRun run = render_fault_scene("memory_arrays_freed",
                                          "#for (I, 1, 20)\n"
                                          "  #declare A = array[5000];\n"
                                          "#end\n"
                                          "sphere { 0, 1 pigment { rgb 1 } }\n",
                                          "--max-memory 16M");
  EXPECT_EQ(run.outcome.code, 0) << run.outcome.output;
  EXPECT_TRUE(run.written);
}

TEST(MemoryLimit, SceneWithinTheLimitRenders) {
  const FaultRun run = render_fault_scene("memory_within", kBigMesh2, "--max-memory 64M");
  EXPECT_NE(run.outcome.output.find("holds 3 items, its count says 100000"), std::string::npos)
      << run.outcome.output << "\n(the charge passed; the list's own check stops it)";
}

TEST(MemoryLimit, BadSizeIsAUsageError) {
  const FaultRun run = render_fault_scene("memory_bad_size", "sphere { 0, 1 }\n", "--max-memory lots");
  EXPECT_EQ(run.outcome.code, 2) << run.outcome.output;
  EXPECT_NE(run.outcome.output.find("--max-memory needs a size"), std::string::npos) << run.outcome.output;
}

}  // namespace
}  // namespace snell::test
