// Particle systems and boids simulate from t = 0 on a fixed step grid every time, so a frame of an
// animation is the same picture whether it is rendered as frame 7 of 1..20 (+SF7, whose clock is
// (7 - 1) / 19 by POV-Ray's rules) or with that clock given directly, and on any number of threads.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "run_command.hpp"

namespace snell {
namespace {

std::string read_bytes(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

TEST(ParticleFrames, AFrameAloneEqualsTheSameClockAnyThreads) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("snell_particle_frames_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  const std::string scene = std::string(SNELL_SOURCE_DIR) + "/scenes/fireworks.pov";
  const std::string common = std::string(SNELL_BINARY) + " +I" + scene + " +W80 +H60 -D ";
  // Frame 7 of 1..20, rendered alone (+SF7 +EF7), is written as a07.png.
  const auto frame = test::run_command(common + "+KFI1 +KFF20 +SF7 +EF7 +WT2 +O" + (dir / "a.png").string());
  const auto clock = test::run_command(common + "+KI0.3157894736842105 +WT1 +O" + (dir / "b.png").string());
  ASSERT_EQ(frame.code, 0) << frame.output;
  ASSERT_EQ(clock.code, 0) << clock.output;
  const std::string a = read_bytes(dir / "a07.png"), b = read_bytes(dir / "b.png");
  std::filesystem::remove_all(dir);
  EXPECT_FALSE(a.empty());
  EXPECT_EQ(a, b);
}

}  // namespace
}  // namespace snell
