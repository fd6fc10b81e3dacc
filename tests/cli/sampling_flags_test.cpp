// The sampling flags on the command line: --spp, --sampler, --filter (both forms), +AM2 and +AG.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "run_command.hpp"

namespace snell {
namespace {

using test::Outcome;

Outcome run(const std::string& args) {
  return test::run_command(std::string(SNELL_BINARY) + " " + args);
}

std::filesystem::path temp(const std::string& name) {
  return std::filesystem::temp_directory_path() / ("snell_sampling_" + std::to_string(getpid()) + name);
}

std::string scene_file() {
  const auto path = temp(".pov");
  std::ofstream(path) << "camera { location -3*z shutter { open 0 close 1 samples 2 } }\n"
                         "light_source { <2,3,-4> rgb 1 }\n"
                         "sphere { 0, 1 pigment { rgb 1 } motion { translate x } }\n";
  return path.string();
}

TEST(SamplingFlags, SppSamplerAndFilterRender) {
  const std::string out = temp(".png").string();
  for (const std::string flags :
       {"--spp 3 --sampler halton --filter tent:1.5", "--spp 2 --sampler stratified", "--filter mitchell"}) {
    const Outcome r = run("render " + scene_file() + " -w 8 -h 6 --quiet -o " + out + " " + flags);
    EXPECT_EQ(r.code, 0) << flags << "\n" << r.output;
  }
  const Outcome pov =
      run("+I" + scene_file() + " +W8 +H6 -D --quiet +O" + out + " --spp=2 --filter=gaussian");
  EXPECT_EQ(pov.code, 0) << pov.output;
  std::filesystem::remove(out);
}

TEST(SamplingFlags, BadValuesAreUsageErrors) {
  const std::string out = temp("_bad.png").string();
  const Outcome filter = run("render " + scene_file() + " -o " + out + " --filter lanczos");
  EXPECT_EQ(filter.code, 2);
  EXPECT_NE(filter.output.find("bad filter 'lanczos'"), std::string::npos) << filter.output;
  const Outcome sampler = run("render " + scene_file() + " -o " + out + " --sampler random");
  EXPECT_EQ(sampler.code, 2);
  EXPECT_NE(sampler.output.find("unknown sampler 'random'"), std::string::npos) << sampler.output;
  EXPECT_EQ(run("render " + scene_file() + " -o " + out + " --spp -1").code, 2);
  EXPECT_EQ(run("render " + scene_file() + " -o " + out + " --aa-method 3").code, 2);
}

TEST(SamplingFlags, AdaptiveMethodTwoIsAcceptedAndOthersWarn) {
  const std::string out = temp("_am.png").string();
  const Outcome two = run("+I" + scene_file() + " +W8 +H6 -D +A0.1 +AM2 +R3 +O" + out);
  EXPECT_EQ(two.code, 0) << two.output;
  EXPECT_EQ(two.output.find("method 2 is not supported"), std::string::npos) << two.output;
  const Outcome three = run("+I" + scene_file() + " +W8 +H6 -D +A0.1 +AM3 +O" + out);
  EXPECT_NE(three.output.find("anti-aliasing method 3 is not supported"), std::string::npos) << three.output;
  std::filesystem::remove(out);
}

/// The "N pixels supersampled" figure of --stats.
long supersampled(const std::string& output) {
  const size_t end = output.find(" pixels supersampled");
  if (end == std::string::npos) return -1;
  const size_t start = output.rfind(' ', end - 1);
  return std::stol(output.substr(start + 1, end - start - 1));
}

TEST(SamplingFlags, AntialiasGammaChangesTheSupersampledPixels) {
  // A dim sphere (a 3.7 scene: linear working colours) on black: its edge is a small linear difference
  // that POV-Ray's default Antialias_Gamma 2.5 makes large enough to supersample; +AG0 compares linearly.
  const auto scene = temp("_ag.pov");
  std::ofstream(scene) << "#version 3.7;\nglobal_settings { assumed_gamma 1 }\ncamera { location -3*z }\n"
                          "sphere { 0, 1 pigment { rgb 0.04 } finish { ambient 1 diffuse 0 } }\n";
  const std::string out = temp("_ag.png").string();
  const std::string common = "+I" + scene.string() + " +W40 +H30 -D +A0.3 --stats +O" + out;
  const Outcome pov = run(common);
  const Outcome linear = run(common + " +AG0");
  const Outcome ini = run(common + " Antialias_Gamma=0");
  ASSERT_EQ(pov.code, 0) << pov.output;
  ASSERT_EQ(linear.code, 0) << linear.output;
  EXPECT_GT(supersampled(pov.output), 0) << pov.output;
  EXPECT_EQ(supersampled(linear.output), 0) << linear.output;  // 3 x 0.04 < 0.3
  EXPECT_EQ(supersampled(ini.output), 0) << ini.output;
  std::filesystem::remove(scene);
  std::filesystem::remove(out);
}

}  // namespace
}  // namespace snell
