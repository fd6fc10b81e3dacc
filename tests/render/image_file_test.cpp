// PNG round trip with POV-Ray 3.7's default sRGB file gamma (IEC 61966-2-1).
#include "snell/io/image_file.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace snell::io {
namespace {

namespace fs = std::filesystem;

TEST(EncodingTest, SrgbCurveKnownValues) {
  EXPECT_NEAR(srgb_encode(0.5), 0.735356983, 1e-8);  // 1.055 * 0.5^(1/2.4) - 0.055
  EXPECT_NEAR(srgb_encode(0.002), 0.02584, 1e-12);   // linear toe: 12.92 x
  EXPECT_NEAR(srgb_decode(srgb_encode(0.18)), 0.18, 1e-12);
  Encoding legacy;
  legacy.passthrough = true;
  EXPECT_DOUBLE_EQ(legacy.encode(0.5), 0.5);
  EXPECT_DOUBLE_EQ(Encoding{}.encode(2.0), 1.0);
  EXPECT_DOUBLE_EQ(Encoding{}.encode(-1.0), 0.0);
}

TEST(ImageFileTest, PngRoundTripAppliesSrgbCurve) {
  Image img(3, 2);
  img.set(0, 0, {0.5, 0.0, 1.0});
  img.set(2, 1, {0.18, 0.002, 0.9});
  const fs::path path = fs::temp_directory_path() / "snell_png_round_trip.png";
  write_image(path, img, {});
  const Image back = read_image(path);
  ASSERT_EQ(back.width, 3);
  ASSERT_EQ(back.height, 2);
  EXPECT_NEAR(back.at(0, 0).r, std::round(0.735356983 * 255) / 255, 1e-6);  // 188/255
  EXPECT_NEAR(back.at(0, 0).b, 1.0, 1e-6);
  EXPECT_NEAR(srgb_decode(back.at(2, 1).r), 0.18, 0.003);
  fs::remove(path);
}

TEST(ImageFileTest, SixteenBitAndExrKeepPrecision) {
  Image img(2, 2);
  img.set(1, 1, {0.25, 0.5, 2.5});
  const fs::path png = fs::temp_directory_path() / "snell_16.png";
  write_image(png, img, {Encoding{}, 16});
  EXPECT_NEAR(srgb_decode(read_image(png).at(1, 1).r), 0.25, 1e-4);
  const fs::path exr = fs::temp_directory_path() / "snell_linear.exr";
  write_image(exr, img, {});
  EXPECT_FLOAT_EQ(read_image(exr).at(1, 1).b, 2.5f);  // linear, unclamped
  fs::remove(png);
  fs::remove(exr);
}

TEST(ImageFileTest, CoverageTravelsAsAlphaInPngAndExr) {
  Image img(4, 3);
  img.clear_alpha();
  img.set(1, 2, {0.5, 0.25, 1.0});
  img.set_alpha(1, 2, 1.0f);
  for (const char* name : {"snell_alpha8.png", "snell_alpha16.png", "snell_alpha.exr"}) {
    const fs::path path = fs::temp_directory_path() / name;
    write_image(path, img, {Encoding{}, std::string(name).find("16") != std::string::npos ? 16 : 8});
    const Image back = read_image(path);
    ASSERT_TRUE(back.has_alpha()) << name;
    EXPECT_EQ(back.alpha_at(1, 2), 1.0f) << name;
    EXPECT_EQ(back.alpha_at(0, 0), 0.0f) << name;
    // Unassociated: colours are not divided by alpha. PNG holds sRGB-encoded values, EXR linear ones.
    const bool png = fs::path(name).extension() == ".png";
    EXPECT_NEAR(png ? srgb_decode(back.at(1, 2).g) : back.at(1, 2).g, 0.25, 0.003) << name;
    fs::remove(path);
  }
  img.alpha.assign(img.alpha.size(), 1.0f);
  img.drop_alpha_if_covered();
  EXPECT_FALSE(img.has_alpha());
}

TEST(ImageFileTest, ErrorsAreReported) {
  Image img(1, 1);
  EXPECT_THROW(write_image("/nonexistent-folder/x.png", img, {}), ImageIoError);
  EXPECT_THROW(write_image(fs::temp_directory_path() / "x.bmpx", img, {}), ImageIoError);
  EXPECT_THROW(read_image("/nonexistent-folder/x.png"), ImageIoError);
}

}  // namespace
}  // namespace snell::io
