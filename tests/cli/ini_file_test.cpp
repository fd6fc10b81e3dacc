// POV-Ray .ini files and animation switches: the frame and clock a scene sees follow POV-Ray's rules
// (clock = initial_clock + (frame - initial_frame) * (final_clock - initial_clock) / (frames - 1)).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "run_command.hpp"

namespace snell {
namespace {

// One folder per test process: ctest runs these tests in parallel processes.
const std::filesystem::path folder =
    std::filesystem::temp_directory_path() / ("snell_ini_test_" + std::to_string(getpid()));

/// Writes a scene that prints its animation values and returns the output of `snell args`.
test::Outcome run_with(const std::string& args, const std::string& ini_text = "") {
  std::filesystem::create_directories(folder);
  std::ofstream(folder / "anim.pov")
      << "#debug concat(\"frame \", str(frame_number, 0, 0), \" clock \", str(clock, 0, 3), \" on \","
         " str(clock_on, 0, 0), \" width \", str(image_width, 0, 0), \" A \", str(A, 0, 1), \"\\n\")\n"
         "sphere { 0, 1 }\n";
  if (!ini_text.empty()) std::ofstream(folder / "anim.ini") << ini_text;
  return test::run_command(std::string(SNELL_BINARY) + " --parse-only " + args);
}

TEST(IniFileTest, IniGivesSceneSizeFramesAndDeclares) {
  const auto r = run_with((folder / "anim.ini").string(),
                          "; comment\n[Section]\nInput_File_Name=anim.pov\nWidth=64\n+h48\n"
                          "Initial_Frame=1\nFinal_Frame=5\nInitial_Clock=0\nFinal_Clock=2\n"
                          "Subset_Start_Frame=3\nDeclare=A=2.5\n");
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("frame 3 clock 1.000 on 1 width 64 A 2.5"), std::string::npos) << r.output;
}

TEST(IniFileTest, SwitchesAfterTheIniOverrideIt) {
  const auto r = run_with("+I" + (folder / "anim.ini").string() + " +W32 +KFI0 +KFF10 +KI0 +KF1 +SF4",
                          "Input_File_Name=anim.pov\nWidth=64\nDeclare=A=1\n");
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("frame 4 clock 0.400 on 1 width 32 A 1.0"), std::string::npos) << r.output;
}

TEST(IniFileTest, AStillHasNoClock) {
  const auto r = run_with((folder / "anim.pov").string() + " Declare=A=0");
  EXPECT_NE(r.output.find("frame 0 clock 0.000 on 0"), std::string::npos) << r.output;
}

TEST(IniFileTest, MissingIniIsAUsageError) {
  const auto r = test::run_command(std::string(SNELL_BINARY) + " --parse-only no_such_file.ini");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("cannot read ini file"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace snell
