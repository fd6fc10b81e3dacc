// User file I/O: `#fopen Handle "name" read|write|append`, `#read (Handle, Var...)`,
// `#write (Handle, item...)`, `#fclose Handle` (POV-Ray 3.7 reference, "File I/O Directives").
// A scene may only touch files in its own folder or the system's temporary folder (reading also from
// the library paths), so a downloaded scene cannot read or overwrite anything else.
#include <cstdio>
#include <fstream>
#include <sstream>
#include <system_error>

#include "snell/sdl/lexer.hpp"
#include "snell/sdl/parser.hpp"

namespace snell::sdl {

namespace {

/// Whether `path` lies inside `root` once both are made absolute and free of `..` and links.
bool lies_inside(const std::filesystem::path& path, const std::filesystem::path& root) {
  std::error_code ec;
  const auto p = std::filesystem::weakly_canonical(std::filesystem::absolute(path, ec), ec);
  const auto r = std::filesystem::weakly_canonical(std::filesystem::absolute(root, ec), ec);
  if (ec) return false;
  const auto relative = p.lexically_relative(r);
  return !relative.empty() && *relative.begin() != "..";
}

/// POV-Ray's #write formats: `%g` for a float, `<%g,%g,...> ` for a vector (parser_tokenizer.cpp,
/// Parse_Write). The trailing space after a vector is POV-Ray's.
std::string format_numeric(const Numeric& n) {
  char buffer[64];
  if (n.size == 1 && !n.color) {
    std::snprintf(buffer, sizeof buffer, "%g", n.x());
    return buffer;
  }
  const int size = n.color ? 5 : n.size;
  std::string text = "<";
  for (int i = 0; i < size; ++i) {
    std::snprintf(buffer, sizeof buffer, i == 0 ? "%g" : ",%g", n.v[static_cast<size_t>(i)]);
    text += buffer;
  }
  return text + "> ";
}

}  // namespace

std::vector<std::filesystem::path> Parser::user_file_roots(bool writing) const {
  const std::filesystem::path scene_folder =
      frames_.front().folder.empty() ? std::filesystem::path(".") : frames_.front().folder;
  std::vector<std::filesystem::path> roots{scene_folder, std::filesystem::temp_directory_path()};
  if (!writing) roots.insert(roots.end(), options_.library_paths.begin(), options_.library_paths.end());
  return roots;
}

std::optional<std::filesystem::path> Parser::find_user_file(const std::string& name, bool writing) const {
  const auto roots = user_file_roots(writing);
  const std::filesystem::path given(name);
  for (const auto& root : roots) {
    const std::filesystem::path candidate = given.is_absolute() ? given : root / given;
    bool allowed = false;
    for (const auto& r : roots) allowed = allowed || lies_inside(candidate, r);
    std::error_code ec;
    if (allowed && (writing || std::filesystem::is_regular_file(candidate, ec))) return candidate;
  }
  return std::nullopt;
}

bool Parser::readable_user_file(const std::string& name) const {
  return find_user_file(name, false).has_value();
}

std::filesystem::path Parser::user_file_path(const std::string& name, const Token& where, bool writing) {
  if (const auto found = find_user_file(name, writing)) {
    if (!writing && options_.on_file_read) options_.on_file_read(*found);
    return *found;
  }
  const std::filesystem::path given(name);
  if (given.is_absolute() || name.find("..") != std::string::npos)
    fail(where.where, "file '" + name +
                          "' is outside the scene's folder and the temporary folder; scenes may " +
                          (writing ? "write" : "read") + " files only there");
  fail(where.where, "cannot find user file '" + name + "' to read");
}

void Parser::directive_fopen(const Token& d) {
  const Token handle = raw_next();
  if (handle.kind != Token::Kind::identifier) fail(handle.where, "expected a file handle name after #fopen");
  const Token name_at = peek();
  const std::string name = parse_string();
  const Token mode = next();
  if (!(mode.is_word("read") || mode.is_word("write") || mode.is_word("append")))
    fail(mode.where, "expected read, write or append after the file name in #fopen");
  UserFile file;
  file.path = user_file_path(name, name_at, !mode.is_word("read"));
  if (mode.is_word("read")) {
    std::ifstream in(file.path, std::ios::binary);
    if (!in) fail(name_at.where, "cannot open user file '" + name + "' for reading");
    std::ostringstream text;
    text << in.rdbuf();
    try {
      file.input = std::make_shared<const std::vector<Token>>(
          lex(text.str(), std::make_shared<const std::string>(file.path.string())));
    } catch (const LocatedError& e) {
      fail(e.where, e.message);
    }
  } else {
    file.output = std::make_shared<std::ofstream>(
        file.path, mode.is_word("append") ? std::ios::app | std::ios::binary : std::ios::binary);
    if (!*file.output) fail(name_at.where, "cannot open user file '" + name + "' for " + mode.text);
    // A file written by the scene may be #included later (strings.inc's Parse_String): forget any
    // earlier tokens of it.
    std::error_code ec;
    const auto written = std::filesystem::weakly_canonical(std::filesystem::absolute(file.path, ec), ec);
    for (auto it = token_cache_.begin(); it != token_cache_.end();) {
      const auto cached = std::filesystem::weakly_canonical(std::filesystem::absolute(it->first, ec), ec);
      it = cached == written ? token_cache_.erase(it) : std::next(it);
    }
  }
  user_files_[handle.text] = std::move(file);
}

void Parser::directive_fclose(const Token&) {
  // POV-Ray accepts #fclose of a handle already closed (by the end of a #read).
  const Token handle = raw_next();
  if (handle.kind != Token::Kind::identifier) fail(handle.where, "expected a file handle name after #fclose");
  user_files_.erase(handle.text);
}

Parser::UserFile& Parser::user_file(const Token& handle) {
  if (handle.kind != Token::Kind::identifier) fail(handle.where, "expected a file handle");
  const auto found = user_files_.find(handle.text);
  if (found == user_files_.end()) fail(handle.where, "'" + handle.text + "' is not an open file (#fopen)");
  return found->second;
}

void Parser::directive_write(const Token&) {
  expect("(", "#write");
  const Token handle = raw_next();
  UserFile& file = user_file(handle);
  if (!file.output) fail(handle.where, "file '" + handle.text + "' is open for reading, not writing");
  const auto out = file.output;  // items may run macros that close the handle
  const auto write = [&](const std::string& text) {
    // Bounded output: a runaway loop may not fill the disk.
    bytes_written_ += text.size();
    if (bytes_written_ > kMaxBytesWritten)
      fail(handle.where,
           "#write: the scene wrote more than " + std::to_string(kMaxBytesWritten >> 20) + " MiB");
    *out << text;
  };
  // Commas are optional, as everywhere POV-Ray reads a list (its Parse_Comma): `#write (F Text)`.
  for (;;) {
    accept(",");
    if (peek().is_symbol(")")) break;
    write(starts_string() ? parse_string() : format_numeric(parse_numeric()));
  }
  expect(")", "#write");
  out->flush();
}

std::optional<Value> Parser::read_user_value(UserFile& file) {
  const auto& tokens = *file.input;
  const auto at = [&]() -> const Token& { return tokens[std::min(file.pos, tokens.size() - 1)]; };
  const auto read_float = [&]() -> std::optional<double> {
    double sign = 1;
    if (at().is_symbol("-") || at().is_symbol("+")) {
      sign = at().is_symbol("-") ? -1 : 1;
      ++file.pos;
      if (at().kind != Token::Kind::number) fail(at().where, "expected a number after the sign");
    }
    if (at().kind != Token::Kind::number) return std::nullopt;
    return sign * tokens[file.pos++].number;
  };
  if (at().kind == Token::Kind::end) return std::nullopt;
  Value value;
  if (at().kind == Token::Kind::string) {
    value.data = tokens[file.pos++].text;
  } else if (at().is_symbol("<")) {
    ++file.pos;
    Numeric n;
    n.size = 0;
    while (const auto c = read_float()) {
      if (n.size == 5) fail(at().where, "a vector has at most 5 components");
      n.v[static_cast<size_t>(n.size++)] = *c;
      if (at().is_symbol(",")) ++file.pos;
    }
    if (!at().is_symbol(">")) fail(at().where, "expected a vector component or '>'");
    ++file.pos;
    if (n.size < 2) fail(at().where, "a vector needs at least 2 components");
    if (n.size == 5) n.color = true;
    value.data = n;
  } else if (const auto f = read_float()) {
    value.data = Numeric::of(*f);
  } else {
    fail(at().where, "expected a float, vector or string in the data file");
  }
  if (at().is_symbol(",")) ++file.pos;
  return value;
}

void Parser::directive_read(const Token&) {
  expect("(", "#read");
  const Token handle = raw_next();
  UserFile& file = user_file(handle);
  if (!file.input) fail(handle.where, "file '" + handle.text + "' is open for writing, not reading");
  bool at_end = false;
  for (;;) {
    accept(",");
    if (peek().is_symbol(")")) break;
    const Token variable = raw_next();
    if (variable.kind != Token::Kind::identifier) fail(variable.where, "expected an identifier to read into");
    if (at_end) continue;
    std::optional<Value> value = read_user_value(file);
    // An existing identifier is updated where it lives; a new one is global, as in POV-Ray.
    if (value) assign(variable.text, std::move(*value));
    at_end = (*file.input)[std::min(file.pos, file.input->size() - 1)].kind == Token::Kind::end;
  }
  expect(")", "#read");
  // At the end of the data the handle is closed and undefined: `#while (defined(F)) #read (F, V)`.
  if (at_end) user_files_.erase(handle.text);
}

}  // namespace snell::sdl
