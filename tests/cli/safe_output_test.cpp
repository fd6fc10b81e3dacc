// Safe output (issue 12): a write that fails (full disk, read-only folder, missing folder, a file where a
// folder should be) is one clear error, exit code 3, and leaves the previous file byte for byte as it was,
// for images, animation frames and resume files. The tests run as root, where folder permissions do not stop
// writes, so full and read-only disks are small tmpfs mounts; where mounting is not permitted they skip.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/mount.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "run_command.hpp"
#include "snell/io/image.hpp"
#include "snell/render/resume_file.hpp"

namespace snell {
namespace {

namespace fs = std::filesystem;

const std::string kPrevious = "the previous output, which a failed write must not touch\n";

/// A per-process scratch folder, removed with everything in it (declared before a ScratchDisk inside it, so
/// that the disk is unmounted first).
struct WorkDir {
  fs::path path = fs::temp_directory_path() / ("snell_safe_output_test_" + std::to_string(getpid()));
  WorkDir() { fs::create_directories(path); }
  ~WorkDir() {
    std::error_code ignored;
    fs::remove_all(path, ignored);
  }
};

fs::path scene_file(const fs::path& dir) {
  const fs::path path = dir / "scene.pov";
  // A noisy pigment, so the PNG does not compress to a few bytes and cannot fit in the full disk.
  std::ofstream(path) << R"(#version 3.7;
camera { location <0, 0, -3> look_at 0 }
light_source { <2, 4, -3>, 1 }
sphere { 0, 1 pigment { granite scale 0.05 } }
)";
  return path;
}

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// A tmpfs of `kilobytes` mounted for one test (unmounted at the end), or nothing where mount is refused.
class ScratchDisk {
 public:
  ScratchDisk(const fs::path& where, int kilobytes) : path_(where) {
    fs::create_directories(path_);
    const std::string options = "size=" + std::to_string(kilobytes) + "k,mode=0777";
    mounted_ = mount("tmpfs", path_.c_str(), "tmpfs", 0, options.c_str()) == 0;
    if (!mounted_) why_ = std::strerror(errno);
  }
  ~ScratchDisk() {
    if (mounted_) umount2(path_.c_str(), MNT_DETACH);
  }
  bool mounted() const { return mounted_; }
  const std::string& why() const { return why_; }
  const fs::path& path() const { return path_; }

  /// Fills the disk to the last byte with a filler file.
  void fill() const {
    const int fd = open((path_ / "filler").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const std::vector<char> block(512, 'x');
    while (write(fd, block.data(), block.size()) > 0) {
    }
    while (write(fd, block.data(), 1) > 0) {
    }
    close(fd);
  }
  bool make_read_only() const {
    return mount(nullptr, path_.c_str(), nullptr, MS_REMOUNT | MS_RDONLY, nullptr) == 0;
  }

 private:
  fs::path path_;
  bool mounted_ = false;
  std::string why_;
};

/// Files other than `keep` left in `dir` (a temporary file a failed write forgot).
std::vector<std::string> leftovers(const fs::path& dir, const std::vector<std::string>& keep) {
  std::vector<std::string> extra;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    if (std::find(keep.begin(), keep.end(), name) == keep.end()) extra.push_back(name);
  }
  return extra;
}

test::Outcome render_to(const fs::path& scene, const fs::path& out, const std::string& extra = "") {
  return test::run_command(std::string(SNELL_BINARY) + " +I" + scene.string() + " +O" + out.string() +
                           " +W80 +H60 " + extra);
}

/// The failed render's message: one `snell: error: cannot write '<out>': ...` line, then exit code 3.
void expect_output_error(const test::Outcome& r, const fs::path& out, const std::string& reason) {
  EXPECT_EQ(r.code, 3) << r.output;
  EXPECT_NE(r.output.find("snell: error: cannot write '" + out.string() + "'"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find(reason), std::string::npos) << r.output;
}

TEST(SafeOutput, MissingFolderIsAnOutputError) {
  const WorkDir work;
  const fs::path& dir = work.path;
  const fs::path out = dir / "no_such_folder" / "out.png";
  expect_output_error(render_to(scene_file(dir), out), out, "No such file or directory");
  EXPECT_FALSE(fs::exists(dir / "no_such_folder"));
}

TEST(SafeOutput, FileInPlaceOfAFolderIsAnOutputError) {
  const WorkDir work;
  const fs::path& dir = work.path;
  std::ofstream(dir / "plain_file") << kPrevious;
  const fs::path out = dir / "plain_file" / "out.png";
  expect_output_error(render_to(scene_file(dir), out), out, "Not a directory");
  EXPECT_EQ(read_bytes(dir / "plain_file"), kPrevious);
}

TEST(SafeOutput, FullDiskKeepsThePreviousImageAndFrame) {
  const WorkDir work;
  const fs::path& dir = work.path;
  const fs::path scene = scene_file(dir);
  ScratchDisk disk(dir / "disk", 64);
  if (!disk.mounted()) GTEST_SKIP() << "cannot mount a tmpfs here (" << disk.why() << ")";
  // A still image, an EXR through the image plugin, and frame 2 of an animation (+KFF/+SF/+EF): the
  // output `frame.png` names the frame file frame2.png, as POV-Ray numbers frames.
  struct Case {
    std::string written, output, flags;
  };
  const std::vector<Case> cases{{"out.png", "out.png", ""},
                                {"out.exr", "out.exr", ""},
                                {"frame2.png", "frame.png", "+KFI1 +KFF4 +SF2 +EF2"}};
  std::vector<std::string> names{"filler"};
  for (const Case& c : cases) {
    std::ofstream(disk.path() / c.written) << kPrevious;
    names.push_back(c.written);
  }
  disk.fill();
  for (const Case& c : cases) {
    const fs::path written = disk.path() / c.written;
    expect_output_error(render_to(scene, disk.path() / c.output, c.flags), written, "");
    EXPECT_EQ(read_bytes(written), kPrevious) << c.written;
  }
  EXPECT_TRUE(leftovers(disk.path(), names).empty());
}

TEST(SafeOutput, ReadOnlyFolderKeepsThePreviousImage) {
  const WorkDir work;
  const fs::path& dir = work.path;
  const fs::path scene = scene_file(dir);
  ScratchDisk disk(dir / "disk", 64);
  if (!disk.mounted()) GTEST_SKIP() << "cannot mount a tmpfs here (" << disk.why() << ")";
  const fs::path out = disk.path() / "out.png";
  std::ofstream(out) << kPrevious;
  ASSERT_TRUE(disk.make_read_only());
  expect_output_error(render_to(scene, out), out, "Read-only file system");
  EXPECT_EQ(read_bytes(out), kPrevious);
}

TEST(SafeOutput, FullDiskKeepsThePreviousResumeFile) {
  const WorkDir work;
  const fs::path& dir = work.path;
  ScratchDisk disk(dir / "disk", 64);
  if (!disk.mounted()) GTEST_SKIP() << "cannot mount a tmpfs here (" << disk.why() << ")";
  const fs::path resume = disk.path() / "out.png.snell-resume";
  std::ofstream(resume) << kPrevious;
  disk.fill();
  // A 64x64 tile of floats (48 KiB) cannot fit in the full disk.
  io::Image image(64, 64);
  const render::Tile tile{0, {0, 0, 64, 64}};
  EXPECT_THROW(render::write_resume_file(resume, 1, image, {tile}), render::ResumeError);
  EXPECT_EQ(read_bytes(resume), kPrevious);
  EXPECT_TRUE(leftovers(disk.path(), {"filler", "out.png.snell-resume"}).empty());
}

}  // namespace
}  // namespace snell
