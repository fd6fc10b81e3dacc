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

/// Words the model formats are made of, so that mutations change structure as well as numbers.
const std::vector<std::string> kModelTokens = {std::string("\xff\xff\xff\x7f", 4),
                                               std::string("\0\0\0\0", 4),
                                               std::string("\xff\xff", 2),
                                               "-1",
                                               "nan",
                                               "1e38",
                                               "\nf 1 2 3\n",
                                               "\nv 1 1 1\n",
                                               "element vertex 99999\n",
                                               "property list uchar int vertex_indices\n",
                                               "format binary_big_endian 1.0\n",
                                               "end_header\n",
                                               "solid ",
                                               "\"count\":1000000",
                                               "\"byteOffset\":4",
                                               "\"uri\":\"data:,\"",
                                               std::string("\x10\x41", 2),
                                               std::string("\x20\x41", 2),
                                               "Kaydara FBX Binary  "};

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
void replay(const std::string& name, const Target& target, size_t min_seeds, int mutations,
            const std::vector<std::string>& tokens = kBinaryTokens) {
  io::image_backend();  // loads the OpenImageIO plugin once, outside the timed calls
  const auto seeds = files_in(kCorpus / name);
  ASSERT_GE(seeds.size(), min_seeds) << name;
  for (size_t i = 0; i < seeds.size(); ++i)
    EXPECT_TRUE(run_timed(target, seeds[i], name + " seed " + std::to_string(i))) << name << " seed " << i;
  for (const auto& input : files_in(kCorpus / name / "regressions"))
    run_timed(target, input, name + " regression");
  Mutator mutator(tokens, 20261123);
  int accepted = 0;
  for (int i = 0; i < mutations && !::testing::Test::HasFailure(); ++i)
    accepted += run_timed(target, mutator.mutate(seeds[size_t(i) % seeds.size()]),
                          name + " mutation " + std::to_string(i));
  EXPECT_GT(accepted, mutations / 100) << name;
  EXPECT_LT(accepted, mutations * 19 / 20) << name;
}

// Image inputs go through OpenImageIO (milliseconds each), resume files through snell alone. Mutation 184
// of the image run is the damaged GIF of fuzz/corpus/image/slow/, which took 10 to 15 s while OpenImageIO
// tried every format's reader; now only the reader its signature or extension names sees it.
TEST(FileFuzzReplay, PngReaders) {
  replay("png", read_png_bytes, 8, 300);
}
TEST(FileFuzzReplay, OtherImageFormatsThroughThePlugin) {
  replay("image", read_image_bytes, 8, 300);
}
TEST(FileFuzzReplay, ResumeFiles) {
  replay("resume", read_resume_bytes, 3, 800);
}
TEST(FileFuzzReplay, Df3DensityFiles) {
  replay("df3", read_df3_bytes, 4, 800);
}
// Through Assimp (and snell's binary PLY reader): every format of kMeshFuzzExtensions has a seed.
TEST(FileFuzzReplay, MeshImporter) {
  replay("mesh", read_mesh_bytes, 11, 400, kModelTokens);
}

}  // namespace
}  // namespace snell::fuzz::test
