// A short run of the parser fuzz target in every build (issue 3): the seed corpus, the reproducers of
// every crash the libFuzzer runs found, and a few thousand seeded mutations of the seeds go through
// LLVMFuzzerTestOneInput. Each must end in a scene or a ParseError, within a time limit; the parser's own
// limits (ParseOptions::max_*) are what stop runaway input, not this test.
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "fuzz/parse_fuzzer.hpp"
#include "mutator.hpp"

namespace snell::fuzz::test {
namespace {

const std::filesystem::path kCorpus = std::filesystem::path(SNELL_SOURCE_DIR) / "fuzz" / "corpus";
/// One input may take this long in a Release build; libFuzzer's runs (tools/fuzz.sh) use the same bound.
constexpr double kMaxSecondsPerInput = 2.0;
constexpr int kMutations = 30000;

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The files of `folder` (not its subfolders), sorted so that the run is the same everywhere.
std::vector<std::filesystem::path> files_in(const std::filesystem::path& folder) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(folder))
    if (entry.is_regular_file()) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

/// Runs one input; returns whether it parsed. Fails the test when it takes too long.
bool run_timed(const std::string& input, const std::string& label) {
  const auto start = std::chrono::steady_clock::now();
  const bool parsed = parse_scene_bytes(reinterpret_cast<const uint8_t*>(input.data()), input.size());
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, kMaxSecondsPerInput) << label << " ran too long; input:\n" << input.substr(0, 2000);
  return parsed;
}

TEST(FuzzReplay, SeedCorpusParses) {
  const auto seeds = files_in(kCorpus);
  ASSERT_GE(seeds.size(), 10u);
  for (const auto& path : seeds) EXPECT_TRUE(run_timed(read_text(path), path.string())) << path;
}

TEST(FuzzReplay, CrashReproducersEndInAnErrorOrAScene) {
  for (const auto& path : files_in(kCorpus / "regressions")) run_timed(read_text(path), path.string());
}

TEST(FuzzReplay, SeededMutationsNeverCrashHangOrExhaustMemory) {
  std::vector<std::string> seeds;
  for (const auto& path : files_in(kCorpus)) seeds.push_back(read_text(path));
  ASSERT_FALSE(seeds.empty());
  Mutator mutator(read_dictionary((kCorpus.parent_path() / "sdl.dict").string()), 20261123);
  ASSERT_GT(mutator.dictionary_size(), 100u);
  int parsed = 0;
  for (int i = 0; i < kMutations; ++i) {
    const std::string input = mutator.mutate(seeds[static_cast<size_t>(i) % seeds.size()]);
    parsed += run_timed(input, "mutation " + std::to_string(i));
    if (HasFailure()) break;
  }
  // Mutations that never break a scene, or never leave one whole, would test nothing.
  EXPECT_GT(parsed, kMutations / 100);
  EXPECT_LT(parsed, kMutations * 19 / 20);
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  EXPECT_LT(usage.ru_maxrss, 2L * 1024 * 1024) << "peak resident memory in KiB";
}

}  // namespace
}  // namespace snell::fuzz::test
