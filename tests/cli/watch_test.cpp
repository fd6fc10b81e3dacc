// --watch (issue 12): a change to a file the scene includes starts a second render, a scene error does not
// end the loop, and SIGINT ends it with exit code 0.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "snell/io/image_file.hpp"

extern char** environ;

namespace snell {
namespace {

namespace fs = std::filesystem;

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

/// Polls `log` until it holds `what` `times` times, for at most 20 s.
bool wait_for(const fs::path& log, const std::string& what, size_t times) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (std::chrono::steady_clock::now() < deadline) {
    if (count(read_text(log), what) >= times) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return false;
}

TEST(Watch, AChangedIncludeFileRendersAgainAndSigintEndsWithZero) {
  const fs::path dir = fs::temp_directory_path() / ("snell_watch_test_" + std::to_string(getpid()));
  fs::create_directories(dir);
  const fs::path scene = dir / "scene.pov", include = dir / "colour.inc", out = dir / "out.png",
                 log = dir / "log.txt";
  std::ofstream(include) << "#declare Colour = rgb <1, 0, 0>;\n";
  std::ofstream(scene) << R"(#version 3.7;
#include "colour.inc"
camera { location <0, 0, -3> look_at 0 }
light_source { <2, 4, -3>, 1 }
sphere { 0, 1 pigment { Colour } }
)";
  std::vector<std::string> args{SNELL_BINARY, "+I" + scene.string(), "+O" + out.string(), "--watch"};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t to_log;
  posix_spawn_file_actions_init(&to_log);
  posix_spawn_file_actions_addopen(&to_log, 2, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = 0;
  ASSERT_EQ(posix_spawn(&pid, argv[0], &to_log, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&to_log);

  const bool first = wait_for(log, "watching 2 files", 1);
  io::Image before;
  if (first) {
    before = io::read_image(out);
    std::ofstream(include) << "#declare Colour = rgb <0, 0, 1>;\n";
  }
  const bool second = first && wait_for(log, "watching 2 files", 2);
  io::Image after;
  if (second) {
    after = io::read_image(out);
    // A half-typed edit is a scene error: printed, and the loop goes on watching.
    std::ofstream(include) << "#declare Colour = rgb <0, 0,\n";
  }
  const bool third = second && wait_for(log, "watching 2 files", 3);
  kill(pid, SIGINT);
  int status = 0;
  waitpid(pid, &status, 0);
  const std::string text = read_text(log);
  ASSERT_TRUE(first) << text;
  ASSERT_TRUE(second) << text;
  ASSERT_TRUE(third) << text;
  EXPECT_NE(text.find(".pov:3:1: error:"), std::string::npos) << text;
  EXPECT_NE(text.find("colour.inc changed; rendering again"), std::string::npos) << text;
  ASSERT_TRUE(WIFEXITED(status)) << text;
  EXPECT_EQ(WEXITSTATUS(status), 0) << text;
  // Without +W/+H, --watch renders at its preview size; the sphere's centre turned from red to blue.
  ASSERT_EQ(after.width, 320);
  ASSERT_EQ(after.height, 240);
  const size_t centre = after.index(160, 120);
  EXPECT_GT(before.rgb[centre], 0.5f);
  EXPECT_LT(before.rgb[centre + 2], 0.1f);
  EXPECT_LT(after.rgb[centre], 0.1f);
  EXPECT_GT(after.rgb[centre + 2], 0.5f);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace snell
