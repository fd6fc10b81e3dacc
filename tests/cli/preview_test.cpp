// The +D render window (issue 12) under a virtual X server: the window's pixels, read back when the render
// ends (hidden option --display-snapshot), must be the finished image's pixels. Without Xvfb the test skips.
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fcntl.h>
#include <poll.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "run_command.hpp"
#include "snell/io/image_file.hpp"

extern char** environ;

namespace snell {
namespace {

namespace fs = std::filesystem;

constexpr const char* kXvfb = "/usr/bin/Xvfb";

fs::path work_dir() {
  const fs::path dir = fs::temp_directory_path() / ("snell_preview_test_" + std::to_string(getpid()));
  fs::create_directories(dir);
  return dir;
}

/// Colours across the whole range, a gradient and a gamma-encoded output, so a window that drops or
/// re-encodes values differs from the file.
fs::path scene_file(const fs::path& dir) {
  const fs::path path = dir / "preview.pov";
  std::ofstream(path) << R"(#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1, -4> look_at 0 }
light_source { <3, 5, -4>, 1 }
background { rgb <0.1, 0.2, 0.4> }
plane { y, -1 pigment { gradient x color_map { [0 rgb 0][1 rgb <1, 0.5, 0.2>] } } }
sphere { 0, 1 pigment { rgb <0.9, 0.3, 0.1> } finish { phong 0.9 } }
)";
  return path;
}

/// A private X server. Xvfb picks a free display number itself (-displayfd) and writes it to a pipe once it
/// accepts connections, so tests running in parallel never share or wait for one.
class VirtualDisplay {
 public:
  VirtualDisplay() {
    int ready_pipe[2];
    if (pipe(ready_pipe) != 0) return;
    std::vector<std::string> args{kXvfb, "-displayfd", "3", "-screen", "0", "320x240x24", "-nolisten", "tcp"};
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
    // Close the read end first: it may be fd 3 itself.
    posix_spawn_file_actions_addclose(&actions, ready_pipe[0]);
    posix_spawn_file_actions_adddup2(&actions, ready_pipe[1], 3);
    if (posix_spawn(&pid_, kXvfb, &actions, nullptr, argv.data(), environ) != 0) pid_ = 0;
    posix_spawn_file_actions_destroy(&actions);
    close(ready_pipe[1]);
    // The display number arrives as a line once the server is up; end of file means it failed.
    pollfd p{ready_pipe[0], POLLIN, 0};
    std::string number;
    for (char c = 0; pid_ && poll(&p, 1, 10000) > 0 && read(ready_pipe[0], &c, 1) == 1 && c != '\n';)
      number += c;
    close(ready_pipe[0]);
    if (!number.empty()) display_ = ":" + number;
  }
  ~VirtualDisplay() {
    if (!pid_) return;
    kill(pid_, SIGTERM);
    waitpid(pid_, nullptr, 0);
  }
  bool ready() const { return !display_.empty(); }
  std::string env() const { return "DISPLAY=" + display_; }

 private:
  pid_t pid_ = 0;
  std::string display_;
};

/// One X server for the tests of this process, stopped at exit (starting one costs up to a second or two).
const VirtualDisplay& shared_display() {
  static const VirtualDisplay display;
  return display;
}

TEST(Preview, WindowShowsTheFinishedImageUnderXvfb) {
  if (!fs::exists(kXvfb)) GTEST_SKIP() << "Xvfb is not installed (apt-get install xvfb xauth)";
  const VirtualDisplay& display = shared_display();
  if (!display.ready()) GTEST_SKIP() << "Xvfb did not start";
  const fs::path dir = work_dir();
  const fs::path out = dir / "out.png", shot = dir / "window.png";
  const test::Outcome r =
      test::run_command(display.env() + " " + SNELL_BINARY + " +I" + scene_file(dir).string() + " +O" +
                        out.string() + " +W80 +H60 +A0.3 +D --display-snapshot " + shot.string());
  if (r.output.find("built without SDL2") != std::string::npos) GTEST_SKIP() << "snell has no SDL2";
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_EQ(r.output.find("no preview window"), std::string::npos) << r.output;
  ASSERT_TRUE(fs::exists(shot)) << r.output;
  const io::Image file = io::read_image(out), window = io::read_image(shot);
  ASSERT_EQ(window.width, 80);
  ASSERT_EQ(window.height, 60);
  size_t differing = 0;
  for (size_t i = 0; i < file.rgb.size(); ++i) differing += file.rgb[i] != window.rgb[i];
  EXPECT_EQ(differing, 0u);
  fs::remove_all(dir);
}

TEST(Preview, PauseKeepsTheWindowOpenAfterTheImageIsWritten) {
  if (!fs::exists(kXvfb)) GTEST_SKIP() << "Xvfb is not installed (apt-get install xvfb xauth)";
  const VirtualDisplay& display = shared_display();
  if (!display.ready()) GTEST_SKIP() << "Xvfb did not start";
  const fs::path dir = work_dir();
  const fs::path out = dir / "paused.png";
  const std::string display_setting = display.env();
  std::vector<std::string> args{
      SNELL_BINARY, "+I" + scene_file(dir).string(), "+O" + out.string(), "+W40", "+H30", "+D", "+P",
      "--quiet"};
  std::vector<char*> argv, env;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::string display_var = display_setting;
  env.push_back(display_var.data());
  env.push_back(nullptr);
  pid_t pid = 0;
  ASSERT_EQ(posix_spawn(&pid, argv[0], nullptr, nullptr, argv.data(), env.data()), 0);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (!fs::exists(out) && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  // The image is written; +P keeps the window (and snell) waiting for a key. Ctrl-C ends the wait.
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  int status = 0;
  const bool still_waiting = waitpid(pid, &status, WNOHANG) == 0;
  kill(pid, SIGINT);
  if (still_waiting) waitpid(pid, &status, 0);
  EXPECT_TRUE(fs::exists(out));
  EXPECT_TRUE(still_waiting);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
  fs::remove_all(dir);
}

TEST(Preview, WithoutADisplayWarnsOnceAndRenders) {
  const fs::path dir = work_dir();
  const fs::path out = dir / "headless.png";
  const std::string snell =
      std::string(SNELL_BINARY) + " +I" + scene_file(dir).string() + " +O" + out.string();
  // POV-Ray's switch, snell's flag and the ini option all ask for the window.
  for (const std::string flag : {"+D", "--display", "Display=on"}) {
    fs::remove(out);
    const test::Outcome r = test::run_command("env -u DISPLAY -u WAYLAND_DISPLAY -u SDL_VIDEODRIVER " +
                                              snell + " +W40 +H30 " + flag);
    EXPECT_EQ(r.code, 0) << r.output;
    const size_t first = r.output.find("no preview window");
    EXPECT_NE(first, std::string::npos) << flag << ": " << r.output;
    EXPECT_EQ(r.output.find("no preview window", first + 1), std::string::npos) << r.output;
    EXPECT_TRUE(fs::exists(out)) << flag;
  }
  // -D (POV-Ray's usual batch switch) asks for none: no warning.
  const test::Outcome off = test::run_command("env -u DISPLAY " + snell + " +W40 +H30 -D");
  EXPECT_EQ(off.code, 0) << off.output;
  EXPECT_EQ(off.output.find("no preview window"), std::string::npos) << off.output;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace snell
