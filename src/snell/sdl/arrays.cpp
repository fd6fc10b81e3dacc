// Arrays (POV-Ray 3.7 reference, "Array Identifiers"): `array[N]...` with an optional initializer,
// element reads anywhere an identifier may stand, and `#declare A[i] = value`.
#include <fmt/format.h>

#include <cmath>

#include "snell/sdl/parser.hpp"

namespace snell::sdl {

namespace {

/// The number of elements, saturated at `limit + 1` so that no product of sizes can overflow.
long long element_count(const std::vector<int>& sizes, long long limit) {
  long long n = 1;
  for (int s : sizes) n = n > limit / s ? limit + 1 : n * s;
  return n;
}

}  // namespace

std::shared_ptr<Array> Parser::parse_array() {
  auto array = std::make_shared<Array>();
  const scene::SourceLocation where = peek().where;
  const auto too_large = [this](const scene::SourceLocation& at) {
    fail(at, "array larger than " + std::to_string(options_.max_array_elements) +
                 " elements (ParseOptions::max_array_elements)");
  };
  // peek_after_value: a directive after the last size must run only once the array is declared.
  while (peek_after_value().is_symbol("[")) {
    const Token open = raw_next();
    // POV-Ray 3.7 allows at most 5 dimensions (parser.h, POV_ARRAY::kMaxDimensions).
    if (array->sizes.size() == 5) fail(open.where, "an array has at most 5 dimensions");
    const double size = parse_float();
    expect("]", "array size");
    if (!(size >= 1) || size != std::floor(size))
      fail(open.where, "an array size must be a whole number of at least 1");
    if (size > static_cast<double>(options_.max_array_elements)) too_large(open.where);
    array->sizes.push_back(static_cast<int>(size));
  }
  if (array->sizes.empty()) fail(where, "expected '[size]' after array");
  const long long elements = element_count(array->sizes, options_.max_array_elements);
  if (elements > options_.max_array_elements) too_large(where);
  array->charge =
      charge_memory(where, static_cast<uint64_t>(elements) * sizeof(std::optional<Value>), "array");
  array->items.resize(static_cast<size_t>(elements));
  if (!peek_after_value().is_symbol("{")) return array;

  // `{ a, b, ... }`, nested once per dimension; every element must be given.
  size_t next = 0;
  const auto fill = [&](auto&& self, size_t dim) -> void {
    const Token open = peek();
    expect("{", "array initializer");
    const int count = array->sizes[dim];
    for (int i = 0; i < count; ++i) {
      // Commas are optional (POV-Ray's Parse_Comma): textures/patterns/tiling.pov breaks lines without.
      if (i > 0) accept(",");
      if (peek().is_symbol("}"))
        fail(peek().where, "array initializer has " + std::to_string(i) + " elements here, expected " +
                               std::to_string(count));
      if (dim + 1 < array->sizes.size())
        self(self, dim + 1);
      else if (starts_numeric() && !starts_string())
        // Arithmetic only, as for any item argument: `<1,2> <3,4>` is two vectors, not a comparison.
        array->items[next++] = Value{parse_argument_numeric()};
      else
        array->items[next++] = parse_rvalue();
    }
    accept(",");  // a trailing comma
    if (!peek().is_symbol("}"))
      fail(open.where, "array initializer has more than " + std::to_string(count) + " elements here");
    raw_next();
  };
  // Fewer elements than the size ends in '}' where ',' is expected: report it as a count mismatch.
  fill(fill, 0);
  return array;
}

size_t Parser::parse_array_index(const Array& array, const Token& name) {
  size_t flat = 0;
  for (size_t dim = 0; dim < array.sizes.size(); ++dim) {
    const Token open = peek();
    if (!open.is_symbol("["))
      fail(open.where, "'" + name.text + "' has " + std::to_string(array.sizes.size()) +
                           " dimension(s); expected '[' for the next index");
    raw_next();
    const double i = std::floor(parse_float());  // POV-Ray truncates fractional indices
    expect("]", "array index");
    if (!(i >= 0 && i < array.sizes[dim]))
      fail(open.where, "index " + fmt::format("{:g}", i) + " is out of range for '" + name.text + "' (size " +
                           std::to_string(array.sizes[dim]) + ")");
    flat = flat * static_cast<size_t>(array.sizes[dim]) + static_cast<size_t>(i);
  }
  return flat;
}

void Parser::inject_array_element(const Array& array, const Token& name) {
  const size_t flat = parse_array_index(array, name);
  if (!array.items[flat]) fail(name.where, "element of '" + name.text + "' read before it was set");
  // A small ring of names, so an element read while another is still pending (A[B[1]]) keeps its value.
  const std::string key = "[element " + std::to_string(element_counter_++ % 16) + "]";
  element_values_[key] = *array.items[flat];
  frames_.back().injected = Token{Token::Kind::identifier, key, 0, name.where};
}

bool Parser::array_element_is_set(const Token& name) {
  const Value* v = lookup(name.text);
  const auto* array = v ? std::get_if<std::shared_ptr<Array>>(&v->data) : nullptr;
  if (!array) fail(name.where, "'" + name.text + "' is not an array");
  const auto held = *array;
  return held->items[parse_array_index(*held, name)].has_value();
}

void Parser::declare_array_element(const Token& name, bool local) {
  const Value* v = lookup(name.text);
  const auto* array = v ? std::get_if<std::shared_ptr<Array>>(&v->data) : nullptr;
  if (!array) fail(name.where, "'" + name.text + "' is not an array");
  (void)local;  // the element belongs to the array wherever it was declared
  const auto held = *array;
  const size_t flat = parse_array_index(*held, name);
  expect("=", "array element assignment");
  Value value = parse_rvalue();
  held->items[flat] = std::move(value);
  if (peek_after_value().is_symbol(";")) raw_next();
}

Numeric Parser::parse_array_function(const Token& name) {
  const std::string& f = name.text;
  expect("(", f.c_str());
  const Token array_name = raw_next();
  const Value* v = array_name.kind == Token::Kind::identifier ? lookup(array_name.text) : nullptr;
  const auto* array = v ? std::get_if<std::shared_ptr<Array>>(&v->data) : nullptr;
  if (!array) fail(array_name.where, f + " needs an array, found '" + array_name.text + "'");
  const auto held = *array;
  if (f == "dimensions") {
    expect(")", f.c_str());
    return Numeric::of(static_cast<double>(held->sizes.size()));
  }
  expect(",", f.c_str());
  const scene::SourceLocation where = peek().where;
  const double dim = std::floor(parse_float());
  expect(")", f.c_str());
  // POV-Ray numbers dimensions from 1; outside them the size is 0 (3.7 reference, "dimension_size").
  if (!(dim >= 1 && dim <= static_cast<double>(held->sizes.size()))) {
    warn(where, "dimension_size: '" + array_name.text + "' has no dimension " + fmt::format("{:g}", dim));
    return Numeric::of(0);
  }
  return Numeric::of(held->sizes[static_cast<size_t>(dim) - 1]);
}

}  // namespace snell::sdl
