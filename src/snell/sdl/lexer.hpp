#pragma once
// Lexer: one source file's text into a token vector, lexed once and replayed by the token source
// (POV-Ray 3.7 reference, "Language Basics": comments nest, `colour` is `color`).
#include <memory>
#include <string>
#include <vector>

#include "snell/sdl/token.hpp"

namespace snell::sdl {

/// Lexes `text`; the last token is always Kind::end. Throws LocatedError on a malformed token.
std::vector<Token> lex(const std::string& text, const std::shared_ptr<const std::string>& file_name);

}  // namespace snell::sdl
