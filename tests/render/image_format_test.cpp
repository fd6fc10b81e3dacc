// The image reader picks exactly one OpenImageIO reader, by signature or extension (issue 12): a damaged
// file is refused by that reader at once instead of being offered to every other format for seconds.
#include "snell/io/image_format.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>

#include "snell/io/image_backend.hpp"
#include "snell/io/image_file.hpp"

namespace snell::io {
namespace {

namespace fs = std::filesystem;

TEST(ImageFormatTest, SignatureWinsOverExtension) {
  // Signature bytes from the format specifications (cited in image_format.cpp).
  EXPECT_EQ(image_format_for(std::string_view("\x89PNG\r\n\x1a\n", 8), ".tga"), "png");
  EXPECT_EQ(image_format_for("\xff\xd8\xff\xe0", ".gif"), "jpeg");
  EXPECT_EQ(image_format_for("GIF89a\x01", ".jpg"), "gif");
  EXPECT_EQ(image_format_for("P6\n2 2\n255\n", ".tga"), "pnm");
  EXPECT_EQ(image_format_for(std::string_view("II*\0", 4), ""), "tiff");
  EXPECT_EQ(image_format_for("#?RADIANCE\n", ".png"), "hdr");
  EXPECT_EQ(image_format_for("\x76\x2f\x31\x01", ".exr"), "openexr");
}

TEST(ImageFormatTest, ExtensionWhenNoSignature) {
  // Targa has no signature: the extension decides, in any letter case.
  EXPECT_EQ(image_format_for(std::string_view("\0\0\x02\0", 4), ".TGA"), "targa");
  EXPECT_EQ(image_format_for("P7 not netpbm", ".pgm"), "pnm");
  EXPECT_EQ(image_format_for("GIF8 damaged", ".gif"), "gif");
  EXPECT_EQ(image_format_for("hello", ".txt"), "");
  EXPECT_EQ(image_format_for("", ""), "");
}

TEST(ImageFormatTest, ClaimedPixelsFromFixedHeaders) {
  // GIF logical screen 0x2080 x 0x6137 (the damaged file of fuzz/corpus/image/slow/): 8320 x 24887.
  EXPECT_EQ(claimed_pixels(std::string_view("GIF8 \0\x80\x20\x37\x61", 10), "gif"), 8320LL * 24887);
  // Targa 640 x 480 at bytes 12 to 15.
  std::string tga(18, '\0');
  tga[12] = '\x80', tga[13] = '\x02', tga[14] = '\xe0', tga[15] = '\x01';
  EXPECT_EQ(claimed_pixels(tga, "targa"), 640 * 480);
  // BMP 3 x -2 (top-down) at bytes 18 to 25.
  std::string bmp(26, '\0');
  bmp[18] = 3;
  bmp[22] = '\xfe', bmp[23] = bmp[24] = bmp[25] = '\xff';
  EXPECT_EQ(claimed_pixels(bmp, "bmp"), 6);
  EXPECT_EQ(claimed_pixels("GIF89a", "gif"), -1);  // too short to say
  EXPECT_EQ(claimed_pixels(std::string(40, 'x'), "jpeg"), -1);
}

TEST(ImageFormatTest, UnknownFormatIsAClearError) {
  const fs::path path =
      fs::temp_directory_path() / ("snell-image-format-" + std::to_string(getpid()) + ".dat");
  std::ofstream(path) << "not an image";
  try {
    read_image(path);
    ADD_FAILURE() << "accepted a text file";
  } catch (const ImageIoError& e) {
    EXPECT_NE(std::string(e.what()).find("not an image format"), std::string::npos) << e.what();
  }
  fs::remove(path);
}

// fuzz/corpus/image/slow/: a 61-byte damaged GIF whose logical screen of 8320 x 24887 OpenImageIO's GIF
// reader allocated and cleared while opening it, for 10 to 20 s. Its header is now refused before the
// plugin sees it; 3 s leaves room for a loaded machine.
TEST(ImageFormatTest, DamagedGifIsRefusedQuickly) {
  const fs::path source =
      fs::path(SNELL_SOURCE_DIR) / "fuzz" / "corpus" / "image" / "slow" / "damaged-gif-probes-all-readers";
  std::ifstream in(source, std::ios::binary);
  ASSERT_TRUE(in) << source;
  in.get();  // the fuzz target's first byte picks the extension (.gif); the rest is the file
  const fs::path path = fs::temp_directory_path() / ("snell-damaged-" + std::to_string(getpid()) + ".gif");
  {
    std::ofstream out(path, std::ios::binary);
    out << in.rdbuf();
  }
  image_backend();  // loads the plugin outside the timed call
  const auto start = std::chrono::steady_clock::now();
  try {
    read_image(path);
    ADD_FAILURE() << "accepted a damaged GIF";
  } catch (const ImageIoError& e) {
    EXPECT_NE(std::string(e.what()).find("claims 207059840 pixels"), std::string::npos) << e.what();
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 3.0);
  fs::remove(path);
}

}  // namespace
}  // namespace snell::io
