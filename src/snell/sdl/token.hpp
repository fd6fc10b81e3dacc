#pragma once
// Tokens of the POV-Ray scene language. Each carries where it was written so that any later error, even
// one raised while replaying a #while loop or a macro body, points at the source text.
#include <string>

#include "snell/scene/source_location.hpp"

namespace snell::sdl {

struct Token {
  enum class Kind { identifier, number, string, symbol, directive, end };
  Kind kind = Kind::end;
  /// Identifier / symbol / directive name (without `#`), or the decoded string literal.
  std::string text;
  double number = 0;
  scene::SourceLocation where;

  bool is_symbol(const char* s) const { return kind == Kind::symbol && text == s; }
  bool is_word(const char* s) const { return kind == Kind::identifier && text == s; }
};

}  // namespace snell::sdl
