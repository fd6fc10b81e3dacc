#pragma once
// The outline of a string set in a TrueType font through FreeType, laid out as POV-Ray's `text` does
// (truetype.cpp): one unit per em, the first glyph's left edge at x = 0, the baseline at y = 0, glyphs
// advanced by their advance width plus legacy `kern` table kerning plus the user's offset.
#include <filesystem>
#include <string>

#include "snell/geometry/outline.hpp"

namespace snell::geometry {

/// Throws std::runtime_error when the font cannot be read. A string without visible glyphs (spaces
/// only) throws std::invalid_argument.
Outline text_outline(const std::filesystem::path& font, const std::string& utf8_text, Vec2 offset);

}  // namespace snell::geometry
