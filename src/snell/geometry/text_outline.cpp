#include "snell/geometry/text_outline.hpp"

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H

#include <memory>
#include <stdexcept>
#include <vector>

namespace snell::geometry {
namespace {

// Code points of a UTF-8 string; a malformed byte stands for itself (Latin-1), as lenient as POV-Ray.
std::vector<char32_t> decode_utf8(const std::string& s) {
  std::vector<char32_t> out;
  for (size_t i = 0; i < s.size();) {
    const auto b = static_cast<unsigned char>(s[i]);
    int extra = b >= 0xF0 ? 3 : b >= 0xE0 ? 2 : b >= 0xC0 ? 1 : 0;
    char32_t cp = extra == 0 ? b : b & (0x3F >> extra);
    bool ok = i + static_cast<size_t>(extra) < s.size() || extra == 0;
    for (int k = 1; ok && k <= extra; ++k) {
      const auto c = static_cast<unsigned char>(s[i + static_cast<size_t>(k)]);
      ok = (c & 0xC0) == 0x80;
      cp = (cp << 6) | (c & 0x3F);
    }
    if (!ok) {
      cp = b;
      extra = 0;
    }
    out.push_back(cp);
    i += static_cast<size_t>(extra) + 1;
  }
  return out;
}

struct LibraryDeleter {
  void operator()(FT_Library lib) const { FT_Done_FreeType(lib); }
};
struct FaceDeleter {
  void operator()(FT_Face face) const { FT_Done_Face(face); }
};

// Collects a glyph's contours as pieces, in font units scaled by `scale` and moved by `shift`.
struct OutlineSink {
  std::vector<CurveSegment>* pieces;
  double scale;
  Vec2 shift;
  Vec2 pen;

  Vec2 point(const FT_Vector* v) const {
    return {shift.u + scale * static_cast<double>(v->x), shift.v + scale * static_cast<double>(v->y)};
  }
  static OutlineSink& of(void* user) { return *static_cast<OutlineSink*>(user); }

  static int move_to(const FT_Vector* to, void* user) {
    of(user).pen = of(user).point(to);
    return 0;
  }
  static int line_to(const FT_Vector* to, void* user) {
    OutlineSink& s = of(user);
    const Vec2 end = s.point(to);
    if (end.u != s.pen.u || end.v != s.pen.v) s.pieces->push_back(line_segment(s.pen, end));
    s.pen = end;
    return 0;
  }
  static int conic_to(const FT_Vector* control, const FT_Vector* to, void* user) {
    OutlineSink& s = of(user);
    const Vec2 end = s.point(to);
    s.pieces->push_back(quadratic_bezier(s.pen, s.point(control), end));
    s.pen = end;
    return 0;
  }
  static int cubic_to(const FT_Vector* c0, const FT_Vector* c1, const FT_Vector* to, void* user) {
    OutlineSink& s = of(user);
    const Vec2 end = s.point(to);
    s.pieces->push_back(cubic_bezier(s.pen, s.point(c0), s.point(c1), end));
    s.pen = end;
    return 0;
  }
};

}  // namespace

Outline text_outline(const std::filesystem::path& font, const std::string& utf8_text, Vec2 offset) {
  FT_Library raw_library = nullptr;
  if (FT_Init_FreeType(&raw_library) != 0) throw std::runtime_error("cannot start FreeType");
  const std::unique_ptr<FT_LibraryRec_, LibraryDeleter> library(raw_library);
  FT_Face raw_face = nullptr;
  if (FT_New_Face(raw_library, font.string().c_str(), 0, &raw_face) != 0)
    throw std::runtime_error("cannot read the font \"" + font.string() + "\"");
  const std::unique_ptr<FT_FaceRec_, FaceDeleter> face(raw_face);
  if (!FT_IS_SCALABLE(raw_face) || raw_face->units_per_EM == 0)
    throw std::runtime_error("\"" + font.string() + "\" is not a scalable (TrueType) font");
  const double scale = 1.0 / raw_face->units_per_EM;

  FT_Outline_Funcs funcs{};
  funcs.move_to = &OutlineSink::move_to;
  funcs.line_to = &OutlineSink::line_to;
  funcs.conic_to = &OutlineSink::conic_to;
  funcs.cubic_to = &OutlineSink::cubic_to;

  std::vector<CurveSegment> pieces;
  Vec2 pen{0, 0};
  FT_UInt previous = 0;
  bool first = true;
  for (const char32_t cp : decode_utf8(utf8_text)) {
    const FT_UInt glyph = FT_Get_Char_Index(raw_face, cp);
    if (FT_Load_Glyph(raw_face, glyph, FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING) != 0)
      throw std::runtime_error("cannot load a glyph of \"" + font.string() + "\"");
    const FT_GlyphSlot slot = raw_face->glyph;
    if (first) {
      // The first glyph's left side bearing is dropped so that it starts at x = 0.
      pen.u = -scale * static_cast<double>(slot->metrics.horiBearingX);
    } else if (FT_HAS_KERNING(raw_face)) {
      FT_Vector kern{};
      FT_Get_Kerning(raw_face, previous, glyph, FT_KERNING_UNSCALED, &kern);
      pen.u += scale * static_cast<double>(kern.x);
    }
    if (slot->format == FT_GLYPH_FORMAT_OUTLINE) {
      OutlineSink sink{&pieces, scale, pen, {}};
      FT_Outline_Decompose(&slot->outline, &funcs, &sink);
    }
    pen.u += scale * static_cast<double>(slot->metrics.horiAdvance) + offset.u;
    pen.v += offset.v;
    previous = glyph;
    first = false;
  }
  if (pieces.empty()) throw std::invalid_argument("the text has no visible glyphs");
  return Outline(std::move(pieces));
}

}  // namespace snell::geometry
