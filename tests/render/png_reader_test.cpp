// snell's own PNG reader must give what OpenImageIO (the plugin every other format goes through) gives, on
// POV-Ray's own include image test.png (4-bit palette, as pigment.pov maps it), and leave to the plugin the
// PNGs whose chunks make OpenImageIO's colours differ from the stored samples (tRNS, gAMA).
#include <gtest/gtest.h>

#include <string>

#include "snell/io/image_backend.hpp"
#include "snell/io/png_reader.hpp"

using namespace snell;

namespace {

TEST(PngReaderTest, MatchesOpenImageIoOnPovRayIncludeImages) {
  for (const char* name : {"test.png"}) {  // the one include PNG without tRNS or gAMA; 4-bit palette
    const std::string path = std::string(POVRAY_INCLUDE_DIR) + "/" + name;
    const auto ours = io::read_png(path);
    ASSERT_TRUE(ours.has_value()) << name;
    const io::ImageBackend& oiio = io::image_backend();
    int width = 0, height = 0, channels = 0;
    float* pixels = nullptr;
    char why[256] = {};
    ASSERT_EQ(oiio.read(path.c_str(), "png", &width, &height, &channels, &pixels, why, sizeof why), 0) << why;
    ASSERT_EQ(ours->width, width) << name;
    ASSERT_EQ(ours->height, height) << name;
    EXPECT_EQ(ours->has_alpha(), channels == 2 || channels == 4) << name;
    int differing = 0;
    for (int p = 0; p < width * height; ++p)
      for (int c = 0; c < 3; ++c) differing += ours->rgb[p * 3 + c] != pixels[p * 4 + c];
    EXPECT_EQ(differing, 0) << name;
    oiio.free(pixels);
  }
}

TEST(PngReaderTest, LeavesGammaAndTransparencyChunksToThePlugin) {
  EXPECT_FALSE(io::read_png(std::string(POVRAY_INCLUDE_DIR) + "/Mount1.png").has_value());   // gAMA
  EXPECT_FALSE(io::read_png(std::string(POVRAY_INCLUDE_DIR) + "/plasma2.png").has_value());  // tRNS
}

TEST(PngReaderTest, OtherFilesAreNotPngs) {
  EXPECT_FALSE(io::read_png("/nonexistent-folder/x.png").has_value());
  EXPECT_FALSE(io::read_png(std::string(POVRAY_INCLUDE_DIR) + "/colors.inc").has_value());
}

}  // namespace
