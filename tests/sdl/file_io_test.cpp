// #fopen / #write / #read / #fclose, and the folders a scene may touch (POV-Ray 3.7 reference,
// "File I/O Directives"; the write formats are POV-Ray's: `%g` floats, `<a,b,c> ` vectors).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "sdl_test_util.hpp"
#include "snell/geometry/sphere.hpp"

namespace snell::sdl {
namespace {

std::string temp_file(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("snell_file_io_test_" + name)).string();
}

std::string contents(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(SdlFileIo, WriteUsesPovRayFormats) {
  const std::string path = temp_file("write.txt");
  test::parse("#fopen F \"" + path +
              "\" write\n#write (F, \"\\\"a\\\",\", 5, \",\", <1, 2.5, 3>, \"\\n\")\n#fclose F");
  EXPECT_EQ(contents(path), "\"a\",5,<1,2.5,3> \n");
  test::parse("#fopen F \"" + path + "\" append\n#write (F, 0.25)\n#fclose F");
  EXPECT_EQ(contents(path), "\"a\",5,<1,2.5,3> \n0.25");
}

TEST(SdlFileIo, ReadsBackFloatsVectorsAndStringsThenUndefinesTheHandle) {
  const std::string path = temp_file("read.txt");
  std::ofstream(path) << "\"Testing 123\", -5, <1, -2, 3>,\n7";
  const auto scene = test::parse("#fopen F \"" + path +
                                 "\" read\n#read (F, S, A, V)\n#declare Count = 0;\n"
                                 "#while (defined(F)) #read (F, B) #declare Count = Count + 1; #end\n"
                                 "#if (strcmp(S, \"Testing 123\") != 0) #error \"wrong string\" #end\n"
                                 "sphere { V + <A, B, Count>, 1 }");
  const auto* s = dynamic_cast<const geometry::Sphere*>(scene.objects.at(0)->shape.get());
  EXPECT_EQ(s->center(), math::Vec3(1 - 5, -2 + 7, 3 + 1));
}

TEST(SdlFileIo, FilesOutsideTheSceneAndTemporaryFoldersAreRefused) {
  EXPECT_NE(test::error_of("#fopen F \"/etc/passwd\" read").find("outside the scene's folder"),
            std::string::npos);
  EXPECT_NE(test::error_of("#fopen F \"../../x.txt\" write").find("outside the scene's folder"),
            std::string::npos);
  EXPECT_NE(test::error_of("#fopen F \"no-such-file.txt\" read").find("cannot find"), std::string::npos);
  const std::string path = temp_file("mode.txt");
  EXPECT_NE(test::error_of("#fopen F \"" + path + "\" write\n#read (F, X)").find("open for writing"),
            std::string::npos);
}

TEST(SdlFileIo, ParseStringWritesAndIncludesATemporaryFile) {
  // strings.inc's Parse_String writes the text to a file in the scene's folder and #includes it; a
  // second call must see the new text, not the first file's cached tokens.
  const auto scene = test::parse(
      "#include \"strings.inc\"\nParse_String(\"#declare Q = 2;\")\nParse_String(\"#declare R = Q + 3;\")\n"
      "sphere { <Q, R, 0>, 1 }");
  const auto* s = dynamic_cast<const geometry::Sphere*>(scene.objects.at(0)->shape.get());
  EXPECT_EQ(s->center(), math::Vec3(2, 5, 0));
  std::filesystem::remove("parse_string.tmp");
}

}  // namespace
}  // namespace snell::sdl
