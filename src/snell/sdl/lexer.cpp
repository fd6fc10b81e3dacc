#include "snell/sdl/lexer.hpp"

#include <cctype>
#include <cstdlib>

#include "snell/sdl/diagnostics.hpp"

namespace snell::sdl {

namespace {

bool is_ident_start(char c) {
  return std::isalpha(static_cast<unsigned char>(c)) || c == '_';
}
bool is_ident_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}
bool is_digit(char c) {
  return std::isdigit(static_cast<unsigned char>(c)) != 0;
}

class Lexer {
 public:
  Lexer(const std::string& text, std::shared_ptr<const std::string> file)
      : text_(text), file_(std::move(file)) {}

  std::vector<Token> run() {
    std::vector<Token> tokens;
    for (;;) {
      skip_space_and_comments();
      Token t;
      t.where = here();
      if (pos_ >= text_.size()) {
        t.kind = Token::Kind::end;
        tokens.push_back(std::move(t));
        return tokens;
      }
      const char c = text_[pos_];
      if (is_ident_start(c)) {
        t.kind = Token::Kind::identifier;
        t.text = read_identifier();
        // POV-Ray treats the British spellings as the same keyword.
        if (t.text == "colour")
          t.text = "color";
        else if (t.text == "colour_map")
          t.text = "color_map";
      } else if (is_digit(c) || (c == '.' && pos_ + 1 < text_.size() && is_digit(text_[pos_ + 1]))) {
        t.kind = Token::Kind::number;
        t.number = read_number(t.where);
      } else if (c == '"') {
        t.kind = Token::Kind::string;
        t.text = read_string(t.where);
      } else if (c == '#') {
        advance();
        skip_space_and_comments();
        // A '#' with no directive name after it is ignored, as POV-Ray does (language/image_size.pov
        // has `look_at <0,2,0>#` before its closing brace).
        if (pos_ >= text_.size() || !is_ident_start(text_[pos_])) continue;
        t.kind = Token::Kind::directive;
        t.text = read_identifier();
      } else {
        t.kind = Token::Kind::symbol;
        t.text = read_symbol(t.where);
      }
      tokens.push_back(std::move(t));
    }
  }

 private:
  scene::SourceLocation here() const { return {file_, line_, column_}; }

  void advance() {
    if (text_[pos_] == '\n') {
      ++line_;
      column_ = 1;
    } else {
      ++column_;
    }
    ++pos_;
  }

  void skip_space_and_comments() {
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (std::isspace(static_cast<unsigned char>(c))) {
        advance();
      } else if (c == '/' && pos_ + 1 < text_.size() && text_[pos_ + 1] == '/') {
        while (pos_ < text_.size() && text_[pos_] != '\n') advance();
      } else if (c == '/' && pos_ + 1 < text_.size() && text_[pos_ + 1] == '*') {
        skip_block_comment();
      } else {
        return;
      }
    }
  }

  // POV-Ray block comments nest: `/* a /* b */ c */` is one comment.
  void skip_block_comment() {
    const scene::SourceLocation start = here();
    int depth = 0;
    while (pos_ < text_.size()) {
      if (text_.compare(pos_, 2, "/*") == 0) {
        ++depth;
        advance();
        advance();
      } else if (text_.compare(pos_, 2, "*/") == 0) {
        advance();
        advance();
        if (--depth == 0) return;
      } else {
        advance();
      }
    }
    throw LocatedError{start, "unterminated comment: end of file inside /* */"};
  }

  std::string read_identifier() {
    const size_t start = pos_;
    while (pos_ < text_.size() && is_ident_char(text_[pos_])) advance();
    return text_.substr(start, pos_ - start);
  }

  double read_number(const scene::SourceLocation& where) {
    const size_t start = pos_;
    while (pos_ < text_.size() && is_digit(text_[pos_])) advance();
    if (pos_ < text_.size() && text_[pos_] == '.') {
      advance();
      while (pos_ < text_.size() && is_digit(text_[pos_])) advance();
    }
    if (pos_ < text_.size() && (text_[pos_] == 'e' || text_[pos_] == 'E')) {
      size_t look = pos_ + 1;
      if (look < text_.size() && (text_[look] == '+' || text_[look] == '-')) ++look;
      if (look < text_.size() && is_digit(text_[look])) {
        while (pos_ < look) advance();
        while (pos_ < text_.size() && is_digit(text_[pos_])) advance();
      }
    }
    const std::string s = text_.substr(start, pos_ - start);
    char* end = nullptr;
    const double value = std::strtod(s.c_str(), &end);
    if (end != s.c_str() + s.size()) throw LocatedError{where, "malformed number '" + s + "'"};
    return value;
  }

  std::string read_string(const scene::SourceLocation& where) {
    advance();  // opening quote
    std::string out;
    for (;;) {
      // A string may span lines, as POV-Ray reads it (shapes3.inc has one); only the end of file ends it.
      if (pos_ >= text_.size()) throw LocatedError{where, "unterminated string: missing closing '\"'"};
      const char c = text_[pos_];
      advance();
      if (c == '"') return out;
      if (c != '\\') {
        out += c;
        continue;
      }
      if (pos_ >= text_.size()) throw LocatedError{where, "unterminated string: missing closing '\"'"};
      const char e = text_[pos_];
      advance();
      switch (e) {
        case 'n':
          out += '\n';
          break;
        case 't':
          out += '\t';
          break;
        case 'r':
          out += '\r';
          break;
        case 'a':
          out += '\a';
          break;
        case 'b':
          out += '\b';
          break;
        case 'f':
          out += '\f';
          break;
        case 'v':
          out += '\v';
          break;
        case '0':
          out += '\0';
          break;
        case '\\':
          out += '\\';
          break;
        case '"':
          out += '"';
          break;
        case '\'':
          out += '\'';
          break;
        default:
          out += '\\';
          out += e;
          break;  // POV-Ray keeps unknown escapes (Windows paths)
      }
    }
  }

  std::string read_symbol(const scene::SourceLocation& where) {
    const char c = text_[pos_];
    const char n = pos_ + 1 < text_.size() ? text_[pos_ + 1] : '\0';
    if ((c == '<' || c == '>' || c == '!') && n == '=') {
      advance();
      advance();
      return std::string{c, '='};
    }
    static const std::string singles = "{}()[]<>,;.+-*/?:&|!=";
    if (singles.find(c) == std::string::npos)
      throw LocatedError{where, std::string("unexpected character '") + c + "'"};
    advance();
    return std::string(1, c);
  }

  const std::string& text_;
  std::shared_ptr<const std::string> file_;
  size_t pos_ = 0;
  int line_ = 1;
  int column_ = 1;
};

}  // namespace

std::vector<Token> lex(const std::string& text, const std::shared_ptr<const std::string>& file_name) {
  return Lexer(text, file_name).run();
}

}  // namespace snell::sdl
