#pragma once
// Which OpenImageIO reader opens an image file, and whether its header is sane enough to hand over.
// OpenImageIO's ImageInput::open tries every other format's reader when the one its extension names refuses
// a file, so a damaged file costs one open per installed format; snell names the one reader instead: by
// the file's leading signature bytes when it has a known one, else by its extension.
#include <filesystem>
#include <string>
#include <string_view>

namespace snell::io {

/// The OpenImageIO format name ("png", "jpeg", "gif", "targa", "pnm", "tiff", "openexr", "hdr", "bmp",
/// "iff") for a file starting with `head`: its signature when it has one (PNG, JPEG, GIF, PNM, TIFF,
/// OpenEXR, Radiance HDR, BMP, IFF), else the format `extension` names (Targa has no signature). Empty
/// when neither is known.
std::string image_format_for(std::string_view head, const std::filesystem::path& extension);

/// Most pixels a GIF, Targa or BMP header may claim (4096 x 4096). OpenImageIO's GIF reader allocates and
/// clears the whole logical screen while opening, before any pixel is read, and the plugin then holds two
/// float copies: a damaged 61-byte GIF claiming 8320 x 24887 spent 10 to 20 s there
/// (fuzz/corpus/image/slow/), and a 46-byte one claiming 7679 x 7453 passed libFuzzer's 25 s limit and
/// would have needed 2 GB (png/regressions/gif-canvas-7679x7453). Such headers are refused first.
inline constexpr long long kMaxClaimedPixels = 1LL << 24;

/// The pixel count the fixed-layout header of a GIF (logical screen), Targa or BMP file claims, read from
/// its first bytes `head` (at least 26 for BMP); -1 for other formats or a header too short to say.
long long claimed_pixels(std::string_view head, std::string_view format);

struct ImageFileHeader {
  std::string format;             ///< empty when unknown (or the file cannot be opened)
  long long claimed_pixels = -1;  ///< -1 when the format's header is not checked
};
/// The format and claimed size of the file at `path`, from its first bytes and its extension.
ImageFileHeader read_image_header(const std::filesystem::path& path);

}  // namespace snell::io
