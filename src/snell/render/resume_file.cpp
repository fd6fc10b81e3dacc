#include "snell/render/resume_file.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <string>
#include <system_error>

namespace snell::render {

namespace fs = std::filesystem;

namespace {

constexpr char kMagic[8] = {'S', 'N', 'E', 'L', 'L', 'R', 'S', 'M'};
constexpr uint32_t kFormatVersion = 1;

template <typename T>
void put(std::ofstream& out, const T& value) {
  out.write(reinterpret_cast<const char*>(&value), sizeof value);
}

template <typename T>
T get(std::ifstream& in, const fs::path& path) {
  T value{};
  if (!in.read(reinterpret_cast<char*>(&value), sizeof value))
    throw ResumeError("resume file '" + path.string() + "' is truncated");
  return value;
}

bool inside(const PixelRect& inner, const PixelRect& outer) {
  return inner.x0 >= outer.x0 && inner.y0 >= outer.y0 && inner.x1 <= outer.x1 && inner.y1 <= outer.y1;
}

}  // namespace

void Fnv1a::add(const void* data, size_t size) {
  const auto* bytes = static_cast<const unsigned char*>(data);
  for (size_t i = 0; i < size; ++i) {
    hash_ ^= bytes[i];
    hash_ *= 0x100000001b3ULL;
  }
}

void Fnv1a::add(const std::string& text) {
  add_value(text.size());
  add(text.data(), text.size());
}

void write_resume_file(const fs::path& path, uint64_t fingerprint, const io::Image& image,
                       const std::vector<Tile>& tiles) {
  // Built piecewise: GCC 12 warns falsely (-Wrestrict) on "." + string + "...".
  std::string temp_name = path.filename().string();
  temp_name.insert(0, 1, '.');
  temp_name.append(".snell-tmp");
  const fs::path temp = path.parent_path() / temp_name;
  {
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    if (!out) throw ResumeError("cannot write resume file '" + path.string() + "': " + std::strerror(errno));
    out.write(kMagic, sizeof kMagic);
    put(out, kFormatVersion);
    put(out, fingerprint);
    put(out, int32_t{image.width});
    put(out, int32_t{image.height});
    put(out, static_cast<uint32_t>(tiles.size()));
    for (const Tile& t : tiles) {
      put(out, int32_t{t.index});
      for (int v : {t.rect.x0, t.rect.y0, t.rect.x1, t.rect.y1}) put(out, int32_t{v});
      for (int y = t.rect.y0; y < t.rect.y1; ++y)
        out.write(reinterpret_cast<const char*>(&image.rgb[image.index(t.rect.x0, y)]),
                  static_cast<std::streamsize>(sizeof(float) * 3 * (t.rect.x1 - t.rect.x0)));
    }
    out.flush();
    if (!out) {
      std::error_code ignored;
      fs::remove(temp, ignored);
      throw ResumeError("cannot write resume file '" + path.string() + "' (disk full?)");
    }
  }
  std::error_code ec;
  fs::rename(temp, path, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(temp, ignored);
    throw ResumeError("cannot write resume file '" + path.string() + "': " + ec.message());
  }
}

ResumeData read_resume_file(const fs::path& path, uint64_t fingerprint, int width, int height) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ResumeError("cannot read resume file '" + path.string() + "'");
  char magic[sizeof kMagic] = {};
  if (!in.read(magic, sizeof magic) || std::memcmp(magic, kMagic, sizeof kMagic) != 0)
    throw ResumeError("'" + path.string() + "' is not a snell resume file");
  if (get<uint32_t>(in, path) != kFormatVersion)
    throw ResumeError("resume file '" + path.string() + "' was written by another version of snell");
  ResumeData data;
  data.fingerprint = get<uint64_t>(in, path);
  if (data.fingerprint != fingerprint)
    throw ResumeError("resume file '" + path.string() +
                      "' belongs to a different scene, flags or snell version; render again without +C");
  const int32_t w = get<int32_t>(in, path), h = get<int32_t>(in, path);
  if (w != width || h != height)
    throw ResumeError("resume file '" + path.string() + "' is for a " + std::to_string(w) + "x" +
                      std::to_string(h) + " image");
  const uint32_t count = get<uint32_t>(in, path);
  const int64_t total_tiles = int64_t{tiles_across(width)} * tiles_down(height);
  if (count > total_tiles) throw ResumeError("resume file '" + path.string() + "' is corrupt (tile count)");
  data.image = io::Image(width, height);
  data.image.clear_alpha();
  for (uint32_t i = 0; i < count; ++i) {
    Tile t;
    t.index = get<int32_t>(in, path);
    t.rect = {get<int32_t>(in, path), get<int32_t>(in, path), get<int32_t>(in, path), get<int32_t>(in, path)};
    if (t.index < 0 || t.index >= total_tiles || t.rect.empty() ||
        !inside(t.rect, full_tile_rect(t.index, width, height)))
      throw ResumeError("resume file '" + path.string() + "' is corrupt (tile " + std::to_string(i) + ")");
    for (int y = t.rect.y0; y < t.rect.y1; ++y) {
      const auto bytes = static_cast<std::streamsize>(sizeof(float) * 3 * (t.rect.x1 - t.rect.x0));
      if (!in.read(reinterpret_cast<char*>(&data.image.rgb[data.image.index(t.rect.x0, y)]), bytes))
        throw ResumeError("resume file '" + path.string() + "' is truncated");
      // The renderer never writes a NaN or infinite pixel (finite_sample.hpp): one here is damage.
      const float* row = &data.image.rgb[data.image.index(t.rect.x0, y)];
      if (!std::all_of(row, row + 3 * (t.rect.x1 - t.rect.x0), [](float v) { return std::isfinite(v); }))
        throw ResumeError("resume file '" + path.string() + "' is corrupt (a pixel is not a number)");
      for (int x = t.rect.x0; x < t.rect.x1; ++x) data.image.set_alpha(x, y, 1.0f);
    }
    data.tiles.push_back(t);
  }
  return data;
}

}  // namespace snell::render
