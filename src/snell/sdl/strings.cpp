// String expressions and the built-in functions on strings (POV-Ray 3.7 reference, "String
// Expressions", "String Functions"; number formats follow POV-Ray's parser_strings.cpp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>

#include "snell/sdl/parser.hpp"
#include "snell/sdl/string_functions.hpp"

namespace snell::sdl {

namespace {

/// The printf format POV-Ray builds for str() and vstr(): width `width` (negative: zero padded),
/// `precision` digits (negative: printf's default).
std::string fixed_format(int width, int precision) {
  char w[16] = "", p[16] = "";
  if (width != 0) std::snprintf(w, sizeof w, "%s%d", width < 0 ? "0" : "", std::min(std::abs(width), 200));
  if (precision >= 0) std::snprintf(p, sizeof p, ".%d", std::min(precision, 100));
  char format[40];
  std::snprintf(format, sizeof format, "%%%s%sf", w, p);
  return format;
}

/// A float argument used as a count or width: NaN and huge values must not reach an int conversion.
int whole(double v) {
  if (!(v == v)) return 0;
  return static_cast<int>(std::clamp(v, -1e9, 1e9));
}

std::string format_fixed(double value, int width, int precision) {
  char buffer[512];
  const int n = std::snprintf(buffer, sizeof buffer, fixed_format(width, precision).c_str(), value);
  // A huge value overflows %f; POV-Ray falls back to %g then.
  if (n < 0 || static_cast<size_t>(n) >= sizeof buffer) std::snprintf(buffer, sizeof buffer, "%g", value);
  return buffer;
}

}  // namespace

bool is_string_function(const std::string& n) {
  return n == "concat" || n == "str" || n == "vstr" || n == "chr" || n == "substr" || n == "strupr" ||
         n == "strlwr" || n == "datetime";
}

bool is_numeric_string_function(const std::string& n) {
  return n == "strlen" || n == "strcmp" || n == "val" || n == "asc" || n == "file_exists";
}

Numeric Parser::parse_string_query(const Token& name) {
  const std::string& f = name.text;
  expect("(", f.c_str());
  const std::string s = parse_string();
  double result = 0;
  if (f == "strcmp") {
    expect(",", "strcmp");
    const int c = s.compare(parse_string());
    result = c < 0 ? -1 : (c > 0 ? 1 : 0);
  } else if (f == "strlen") {
    result = static_cast<double>(s.size());
  } else if (f == "asc") {
    result = s.empty() ? 0 : static_cast<unsigned char>(s[0]);
  } else if (f == "val") {
    result = std::atof(s.c_str());
  } else {  // file_exists: only where the scene may read (file_io.cpp)
    result = readable_user_file(s) ? 1 : 0;
  }
  expect(")", f.c_str());
  return Numeric::of(result);
}

std::string Parser::parse_string() {
  const Token t = next();
  if (t.kind == Token::Kind::string) return t.text;
  if (t.kind != Token::Kind::identifier) fail(t.where, "expected a string");
  if (const Value* v = lookup(t.text)) {
    if (const auto* s = std::get_if<std::string>(&v->data)) return *s;
    fail(t.where, "expected a string, but '" + t.text + "' is a " + v->type_name());
  }
  const std::string& f = t.text;
  if (!is_string_function(f)) fail(t.where, "expected a string, found '" + f + "'");
  expect("(", f.c_str());
  std::string result = parse_string_function(t);
  if (static_cast<long long>(result.size()) > options_.max_string_length)
    fail(t.where, "string longer than " + std::to_string(options_.max_string_length) +
                      " characters (ParseOptions::max_string_length)");
  return result;
}

std::string Parser::parse_string_function(const Token& name) {
  const std::string& f = name.text;
  std::string result;
  if (f == "concat") {
    for (;;) {
      result += parse_string();
      if (static_cast<long long>(result.size()) > options_.max_string_length) return result;
      if (accept(")")) break;
      expect(",", "concat");
    }
    return result;
  }
  if (f == "str") {
    const double value = parse_float();
    expect(",", "str");
    const int width = whole(parse_float());
    expect(",", "str");
    const int precision = whole(parse_float());
    expect(")", "str");
    return format_fixed(value, width, precision);
  }
  if (f == "vstr") {
    // vstr(N, V, separator, width, precision): N (2..5) components, each formatted as str() does.
    const int count = std::clamp(whole(parse_float()), 2, 5);
    expect(",", "vstr");
    const Numeric v = parse_numeric();
    expect(",", "vstr");
    const std::string separator = parse_string();
    expect(",", "vstr");
    const int width = whole(parse_float());
    expect(",", "vstr");
    const int precision = whole(parse_float());
    expect(")", "vstr");
    for (int i = 0; i < count; ++i) {
      const double c = v.size == 1 && !v.color ? v.x() : (i < (v.color ? 5 : v.size) ? v.v[size_t(i)] : 0);
      result += (i ? separator : "") + format_fixed(c, width, precision);
    }
    return result;
  }
  if (f == "datetime") {
    // datetime(days since 2000-01-01 [, strftime format]); POV-Ray formats in UTC.
    const double days = parse_float();
    if (!(std::fabs(days) < 1e7)) fail(name.where, "datetime needs days within 10 million of 2000-01-01");
    std::string format = "%Y-%m-%d %H:%M:%SZ";
    if (accept(",")) format = parse_string();
    expect(")", "datetime");
    if (format.empty() || format.size() > 200)
      fail(name.where, "datetime format must have 1 to 200 characters");
    const std::time_t stamp = static_cast<std::time_t>(std::floor((days + 10957) * 86400 + 0.5));
    std::tm utc{};
    gmtime_r(&stamp, &utc);
    char buffer[1024];
    const size_t n = std::strftime(buffer, sizeof buffer, format.c_str(), &utc);
    return std::string(buffer, n);
  }
  if (f == "chr") {
    const double c = parse_float();
    expect(")", "chr");
    if (!(c >= 1 && c < 256)) fail(name.where, "chr needs a character code from 1 to 255");
    return std::string(1, static_cast<char>(static_cast<int>(c)));
  }
  if (f == "substr") {
    const std::string s = parse_string();
    expect(",", "substr");
    const scene::SourceLocation where = peek().where;
    const int start = whole(parse_float());
    expect(",", "substr");
    const int count = whole(parse_float());
    expect(")", "substr");
    if (start < 1 || count < 0 ||
        static_cast<long long>(start) - 1 + count > static_cast<long long>(s.size()))
      fail(where, "substr(\"" + s.substr(0, 40) + "\", " + std::to_string(start) + ", " +
                      std::to_string(count) + ") reaches outside the string");
    return s.substr(static_cast<size_t>(start - 1), static_cast<size_t>(count));
  }
  result = parse_string();
  expect(")", f.c_str());
  for (char& c : result)
    c = static_cast<char>(f == "strupr" ? std::toupper(static_cast<unsigned char>(c))
                                        : std::tolower(static_cast<unsigned char>(c)));
  return result;
}

}  // namespace snell::sdl
