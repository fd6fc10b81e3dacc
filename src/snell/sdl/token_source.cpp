// The token source: a stack of token vectors (the scene file, include files, macro bodies) that the
// directives push, pop and rewind. Each file is lexed once; #while loops and macro calls replay tokens.
#include <algorithm>
#include <fstream>
#include <iostream>
#include <sstream>

#include "snell/sdl/lexer.hpp"
#include "snell/sdl/parser.hpp"

namespace snell::sdl {

namespace {

bool opens_block(const std::string& d) {
  return d == "if" || d == "ifdef" || d == "ifndef" || d == "while" || d == "switch" || d == "macro" ||
         d == "for";
}

std::optional<std::string> read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

std::shared_ptr<const std::vector<Token>> Parser::tokens_of(const std::string& name,
                                                            const std::string& text) {
  if (const auto it = token_cache_.find(name); it != token_cache_.end()) return it->second;
  auto shared_text = std::make_shared<const std::string>(text);
  texts_.add(name, shared_text);
  std::shared_ptr<const std::vector<Token>> tokens;
  try {
    tokens = std::make_shared<const std::vector<Token>>(
        lex(*shared_text, std::make_shared<const std::string>(name)));
  } catch (const LocatedError& e) {
    fail(e.where, e.message);
  }
  token_cache_[name] = tokens;
  return tokens;
}

void Parser::push_file(const std::filesystem::path& path, Frame::Kind kind,
                       const scene::SourceLocation& site) {
  if (options_.on_file_read) options_.on_file_read(path);
  const auto text = read_file(path);
  if (!text) fail(site, "cannot open file '" + path.string() + "'");
  Frame f;
  f.kind = kind;
  f.tokens = tokens_of(path.string(), *text);
  f.folder = path.parent_path();
  f.call_site = site;
  f.saved_version = version_;
  frames_.push_back(std::move(f));
}

void Parser::check_frame_end() {
  const size_t top = frames_.size() - 1;
  if (!conds_.empty() && conds_.back().frame == top) {
    const Cond& c = conds_.back();
    fail(c.where, c.kind == Cond::Kind::macro_call
                      ? "end of file inside a macro call"
                      : "this block has no matching #end before the end of the file");
  }
}

const Token& Parser::raw_peek() {
  if (frames_.back().injected) return *frames_.back().injected;
  for (;;) {
    Frame& f = frames_.back();
    const Token& t = (*f.tokens)[f.pos];
    if (t.kind != Token::Kind::end || f.kind != Frame::Kind::include) return t;
    // The end of an include file: back to the includer, with its #version (POV-Ray 3.7 "#include").
    check_frame_end();
    version_ = f.saved_version;
    frames_.pop_back();
    scopes_.pop_back();
  }
}

Token Parser::raw_next() {
  if (auto& injected = frames_.back().injected) {
    Token t = std::move(*injected);
    injected.reset();
    return t;
  }
  const Token t = raw_peek();
  Frame& f = frames_.back();
  if (t.kind != Token::Kind::end) ++f.pos;
  count_token(t);
  return t;
}

void Parser::count_token(const Token& t) {
  if (++tokens_read_ > options_.max_tokens)
    fail(t.where, "the scene read more than " + std::to_string(options_.max_tokens) +
                      " tokens (ParseOptions::max_tokens): a runaway loop or macro recursion?");
}

const Token& Parser::peek() {
  for (;;) {
    const Token& t = raw_peek();
    if (t.kind == Token::Kind::directive) {
      const Token d = raw_next();
      handle_directive(d);
      continue;
    }
    if (t.kind == Token::Kind::identifier) {
      if (const Value* v = lookup(t.text)) {
        if (const auto* m = std::get_if<std::shared_ptr<const Macro>>(&v->data)) {
          const auto macro = *m;
          const Token name = raw_next();
          invoke_macro(name, macro);
          continue;
        }
        if (const auto* array = std::get_if<std::shared_ptr<Array>>(&v->data)) {
          const Frame& f = frames_.back();
          if (!f.injected && f.pos + 1 < f.tokens->size() && (*f.tokens)[f.pos + 1].is_symbol("[")) {
            const auto held = *array;
            const Token name = raw_next();
            inject_array_element(*held, name);
            continue;
          }
        }
      }
    }
    if (t.kind == Token::Kind::end) check_frame_end();
    return t;
  }
}

Token Parser::next() {
  const Token t = peek();
  if (t.kind == Token::Kind::end) fail(t.where, "unexpected end of file");
  raw_next();
  return t;
}

const Token& Parser::peek_after_value() {
  for (;;) {
    const Token& t = raw_peek();
    if (t.kind != Token::Kind::directive) return t;
    const bool closes_if_or_macro =
        t.text == "end" && !conds_.empty() && conds_.back().frame == frames_.size() - 1 &&
        (conds_.back().kind == Cond::Kind::macro_call || conds_.back().kind == Cond::Kind::if_);
    if (!(t.text == "else" || t.text == "elseif" || closes_if_or_macro)) return t;
    const Token d = raw_next();
    handle_directive(d);
  }
}

Token Parser::skip_to(std::initializer_list<const char*> targets, const Token& opener) {
  int depth = 0;
  for (;;) {
    const Frame& f = frames_.back();
    const Token& t = (*f.tokens)[f.pos];
    if (t.kind == Token::Kind::end) fail(opener.where, "#" + opener.text + " has no matching #end");
    ++frames_.back().pos;
    count_token(t);
    if (t.kind != Token::Kind::directive) continue;
    if (depth == 0) {
      for (const char* target : targets)
        if (t.text == target) return t;
    }
    if (opens_block(t.text))
      ++depth;
    else if (t.text == "end")
      --depth;
  }
}

void Parser::skip_block(const std::string& what) {
  const Token open = next();
  if (!open.is_symbol("{")) fail(open.where, "expected '{' after " + what);
  int depth = 1;
  while (depth > 0) {
    const Token t = raw_next();
    if (t.kind == Token::Kind::end) fail(open.where, "missing '}' for this " + what + " block");
    if (t.is_symbol("{"))
      ++depth;
    else if (t.is_symbol("}"))
      --depth;
  }
}

void Parser::handle_directive(const Token& d) {
  // A directive met while a directive's value is read runs inside it: `#while` around an unfinished
  // `#declare N = #switch ...` nests one level deeper per iteration (a fuzzer find).
  const NestingGuard guard(*this, d.where);
  const std::string& n = d.text;
  if (n == "declare") return directive_declare(d, false);
  if (n == "local") return directive_declare(d, true);
  if (n == "undef") {
    const Token name = raw_next();
    if (name.kind != Token::Kind::identifier) fail(name.where, "expected an identifier after #undef");
    for (auto it = scopes_.rbegin(); it != scopes_.rend(); ++it)
      if (it->erase(name.text)) return;
    warn(name.where, "#undef of '" + name.text + "', which is not declared");
    return;
  }
  if (n == "if") return directive_if(d, parse_directive_float() != 0);
  if (n == "ifdef" || n == "ifndef") {
    expect("(", "#ifdef");
    const Token name = raw_next();
    if (name.kind != Token::Kind::identifier) fail(name.where, "expected an identifier in #" + n);
    bool defined = lookup(name.text) != nullptr || user_files_.count(name.text) > 0;
    if (raw_peek().is_symbol("[")) defined = array_element_is_set(name);  // `#ifdef (A[i])`
    expect(")", "#ifdef");
    return directive_if(d, n == "ifdef" ? defined : !defined);
  }
  if (n == "else" || n == "elseif") return directive_else(d);
  if (n == "end") return directive_end(d);
  if (n == "while") return directive_while(d);
  if (n == "switch") return directive_switch(d);
  if (n == "case" || n == "range") {
    // Reached while running a matching clause: POV-Ray falls through into the next clause.
    if (conds_.empty() || conds_.back().kind != Cond::Kind::switch_)
      fail(d.where, "#" + n + " outside #switch");
    parse_numeric();
    return;
  }
  if (n == "break") return directive_break(d);
  if (n == "macro") return directive_macro(d);
  if (n == "include") return directive_include(d);
  if (n == "version") {
    version_ = parse_directive_float();
    if (peek_after_value().is_symbol(";")) raw_next();
    return;
  }
  if (n == "debug" || n == "warning" || n == "error") {
    const std::string text = parse_string();
    if (n == "error") fail(d.where, "#error: " + text);
    if (n == "warning")
      warn(d.where, text);
    else
      message(text);
    return;
  }
  if (n == "default") return directive_default(d);
  if (n == "for") return directive_for(d);
  if (n == "fopen") return directive_fopen(d);
  if (n == "fclose") return directive_fclose(d);
  if (n == "read") return directive_read(d);
  if (n == "write") return directive_write(d);
  fail(d.where, "unknown directive #" + n);
}

void Parser::directive_declare(const Token& d, bool local) {
  Token name = raw_next();
  if (name.is_word("deprecated")) {
    // POV-Ray 3.7 `#declare deprecated [once] "message" Name = ...`: the message is for users of Name.
    if (raw_peek().is_word("once")) raw_next();
    parse_string();
    name = raw_next();
  }
  if (name.kind != Token::Kind::identifier) fail(name.where, "expected an identifier after #" + d.text);
  static const char* const reserved[] = {"x",  "y",       "z",     "t",           "u",           "v",
                                         "pi", "true",    "false", "on",          "off",         "yes",
                                         "no", "version", "clock", "image_width", "image_height"};
  for (const char* r : reserved)
    if (name.text == r) fail(name.where, "'" + name.text + "' is a reserved word and cannot be declared");
  if (raw_peek().is_symbol("[")) return declare_array_element(name, local);
  const size_t scope = scopes_.size() - 1;
  const Token eq = raw_next();
  if (!eq.is_symbol("=")) fail(eq.where, "expected '=' after #" + d.text + " " + name.text);
  Value value = parse_rvalue();
  // Arrays are values: `#declare B = A` copies, so later element assignments to one leave the other.
  if (auto* array = std::get_if<std::shared_ptr<Array>>(&value.data))
    try {  // the copy is charged again against --max-memory (memory/budget.hpp)
      *array = std::make_shared<Array>(**array);
    } catch (const memory::BudgetExceeded& e) {
      fail(eq.where, e.what());
    }
  if (auto* object = std::get_if<ParsedObject>(&value.data); object && object->name.empty())
    object->name = name.text;
  // #local lands in the scope where the directive was written, even when the value came from a macro
  // whose #end has not run yet (`#local M = Matrix_Trans(...)`, `#local P = FindTmp(...)` ending `Q;`).
  if (local)
    scopes_[scope][name.text] = std::move(value);
  else
    declare(name.text, std::move(value), false);
  if (peek_after_value().is_symbol(";")) raw_next();
}

void Parser::directive_if(const Token& d, bool condition) {
  for (;;) {
    if (condition) {
      conds_.push_back({Cond::Kind::if_, frames_.size() - 1, 0, 0, d.where});
      return;
    }
    const Token stop = skip_to({"else", "elseif", "end"}, d);
    if (stop.text == "end") return;
    if (stop.text == "else")
      condition = true;
    else
      condition = parse_directive_float() != 0;
  }
}

void Parser::directive_else(const Token& d) {
  if (conds_.empty() || conds_.back().frame != frames_.size() - 1 ||
      (conds_.back().kind != Cond::Kind::if_ && conds_.back().kind != Cond::Kind::switch_))
    fail(d.where, "#" + d.text + " without a matching #if");
  if (conds_.back().kind == Cond::Kind::switch_) return;  // a matching #case falls through #else
  // The branch that ran is over: skip the rest up to the #end.
  skip_to({"end"}, d);
  conds_.pop_back();
}

void Parser::directive_end(const Token& d) {
  if (conds_.empty() || conds_.back().frame != frames_.size() - 1)
    fail(d.where, "#end without a matching #if, #while, #switch or #macro");
  Cond& c = conds_.back();
  switch (c.kind) {
    case Cond::Kind::if_:
    case Cond::Kind::switch_:
      conds_.pop_back();
      return;
    case Cond::Kind::macro_call:
      end_macro();
      return;
    case Cond::Kind::while_: {
      if (++c.iterations >= options_.max_while_iterations)
        fail(c.where, "#while loop ran more than " + std::to_string(options_.max_while_iterations) +
                          " iterations (raise the limit with --max-loop)");
      frames_.back().pos = c.resume_pos;
      if (parse_directive_float() != 0) return;
      const Token start{Token::Kind::directive, "while", 0, c.where};
      conds_.pop_back();
      skip_to({"end"}, start);
      return;
    }
    case Cond::Kind::for_: {
      if (++c.iterations >= options_.max_while_iterations)
        fail(c.where, "#for loop ran more than " + std::to_string(options_.max_while_iterations) +
                          " iterations (raise the limit with --max-loop)");
      const ForLoop& loop = for_loops_.back();
      // The body may change the counter; POV-Ray steps from its current value.
      const Value* counter = lookup(loop.variable);
      const auto* n = counter ? std::get_if<Numeric>(&counter->data) : nullptr;
      if (!n) fail(c.where, "#for counter '" + loop.variable + "' is no longer a number");
      const double next = n->x() + loop.step;
      if (loop.step > 0 ? next <= loop.end : next >= loop.end) {
        declare(loop.variable, Value{Numeric::of(next)}, macro_depth_ > 0);
        frames_.back().pos = c.resume_pos;
        return;
      }
      conds_.pop_back();
      for_loops_.pop_back();
      return;
    }
  }
}

void Parser::directive_break(const Token& d) {
  // Leaves the innermost #switch, #while or #for, closing the #if blocks open inside it (POV-Ray 3.7
  // reference, "The #break Directive").
  size_t loop = conds_.size();
  while (loop > 0) {
    const Cond& c = conds_[loop - 1];
    if (c.frame != frames_.size() - 1 || c.kind == Cond::Kind::macro_call) {
      loop = 0;
      break;
    }
    if (c.kind == Cond::Kind::switch_ || c.kind == Cond::Kind::while_ || c.kind == Cond::Kind::for_) break;
    --loop;
  }
  if (loop == 0) fail(d.where, "#break outside #switch, #while or #for");
  while (conds_.size() >= loop) {
    skip_to({"end"}, d);
    if (conds_.back().kind == Cond::Kind::for_) for_loops_.pop_back();
    conds_.pop_back();
  }
}

void Parser::directive_for(const Token& d) {
  expect("(", "#for");
  const Token name = raw_next();
  if (name.kind != Token::Kind::identifier) fail(name.where, "expected the counter's name in #for");
  expect(",", "#for");
  const double start = parse_float();
  expect(",", "#for");
  const double end = parse_float();
  double step = 1;
  if (accept(",")) step = parse_float();
  expect(")", "#for");
  if (step == 0) fail(d.where, "#for step is zero: the loop would never end");
  // The counter is set even when the body never runs (POV-Ray leaves it at the start value).
  declare(name.text, Value{Numeric::of(start)}, macro_depth_ > 0);
  if (step > 0 ? start > end : start < end) {
    skip_to({"end"}, d);
    return;
  }
  conds_.push_back({Cond::Kind::for_, frames_.size() - 1, frames_.back().pos, 0, d.where});
  for_loops_.push_back({name.text, end, step});
}

void Parser::directive_default(const Token& d) {
  expect("{", "#default");
  for (;;) {
    const Token t = peek();
    if (t.is_symbol("}")) {
      raw_next();
      return;
    }
    raw_next();
    if (t.is_word("texture")) {
      auto texture = std::make_shared<material::Texture>(*parse_texture_block());
      texture->below = nullptr;
      default_texture_ = std::move(texture);
    } else if (t.is_word("pigment")) {
      auto texture = std::make_shared<material::Texture>(*default_texture_);
      texture->pigment = parse_pigment_block(texture->pigment);
      default_texture_ = std::move(texture);
    } else if (t.is_word("finish")) {
      auto texture = std::make_shared<material::Texture>(*default_texture_);
      texture->finish = parse_finish_block(texture->finish);
      default_texture_ = std::move(texture);
    } else if (t.is_word("normal")) {
      warn(t.where, "normal is not supported yet; ignored");
      skip_block("normal");
    } else {
      fail(t.where, "unexpected '" + t.text + "' in #default (expected texture, pigment, finish or normal)");
    }
  }
  (void)d;
}

void Parser::directive_while(const Token& d) {
  const size_t resume = frames_.back().pos;
  if (parse_directive_float() != 0) {
    conds_.push_back({Cond::Kind::while_, frames_.size() - 1, resume, 0, d.where});
    return;
  }
  skip_to({"end"}, d);
}

void Parser::directive_switch(const Token& d) {
  const double value = parse_directive_float();
  for (;;) {
    const Token clause = skip_to({"case", "range", "else", "end"}, d);
    if (clause.text == "end") return;
    bool match = clause.text == "else";
    if (clause.text == "case") {
      expect("(", "#case");
      match = parse_directive_float() == value;
      expect(")", "#case");
    } else if (clause.text == "range") {
      expect("(", "#range");
      const double lo = parse_directive_float();
      expect(",", "#range");
      const double hi = parse_directive_float();
      expect(")", "#range");
      match = value >= lo && value <= hi;
    }
    if (match) {
      conds_.push_back({Cond::Kind::switch_, frames_.size() - 1, 0, 0, d.where});
      return;
    }
  }
}

void Parser::directive_macro(const Token& d) {
  auto macro = std::make_shared<Macro>();
  const Token name = raw_next();
  if (name.kind != Token::Kind::identifier) fail(name.where, "expected the macro's name after #macro");
  macro->name = name.text;
  macro->where = name.where;
  if (!raw_next().is_symbol("(")) fail(name.where, "expected '(' after the macro name");
  // Commas between parameters are optional and one may end the list, as POV-Ray's Parse_Comma allows
  // (shapes3.inc has both `Border_Scale_y_ Merge_On,` and `Merge_, )`).
  for (;;) {
    const Token p = raw_next();
    if (p.is_symbol(")")) break;
    if (p.kind != Token::Kind::identifier) fail(p.where, "expected a parameter name or ')'");
    macro->parameters.push_back(p.text);
    if (raw_peek().is_symbol(",")) raw_next();
  }
  macro->tokens = frames_.back().tokens;
  macro->body_start = frames_.back().pos;
  skip_to({"end"}, d);
  // Macros are always global in POV-Ray 3.7.
  const std::string macro_name = macro->name;
  scopes_.front()[macro_name] = Value{std::shared_ptr<const Macro>(std::move(macro))};
}

void Parser::invoke_macro(const Token& name, const std::shared_ptr<const Macro>& macro) {
  if (macro_depth_ >= options_.max_macro_depth)
    fail(name.where, "macro calls nested deeper than " + std::to_string(options_.max_macro_depth) +
                         " (runaway recursion?)");
  expect("(", ("call of macro " + macro->name).c_str());
  std::map<std::string, Value> locals;
  std::vector<std::pair<std::string, std::string>> by_reference;
  size_t count = 0;
  if (!peek().is_symbol(")")) {
    for (;;) {
      // POV-Ray passes a lone declared identifier by reference: the macro's #declare of the parameter
      // changes the caller's identifier.
      const Token& first = peek();
      const Frame& top = frames_.back();
      const bool lone =
          first.kind == Token::Kind::identifier && !top.injected && lookup(first.text) &&
          first.text[0] != '[' && top.pos + 1 < top.tokens->size() &&
          ((*top.tokens)[top.pos + 1].is_symbol(",") || (*top.tokens)[top.pos + 1].is_symbol(")"));
      if (lone && count < macro->parameters.size())
        by_reference.emplace_back(macro->parameters[count], first.text);
      Value arg = parse_rvalue();
      if (count < macro->parameters.size()) locals[macro->parameters[count]] = std::move(arg);
      ++count;
      if (accept(")")) break;
      expect(",", "macro arguments");
    }
  } else {
    next();
  }
  if (count != macro->parameters.size())
    fail(name.where, "macro " + macro->name + " takes " + std::to_string(macro->parameters.size()) +
                         " parameter(s), called with " + std::to_string(count));
  Frame f;
  f.kind = Frame::Kind::macro;
  f.tokens = macro->tokens;
  f.pos = macro->body_start;
  f.folder = frames_.back().folder;
  f.call_site = name.where;
  f.scope = scopes_.size();
  f.parameters = macro->parameters;
  f.by_reference = std::move(by_reference);
  frames_.push_back(std::move(f));
  scopes_.push_back(std::move(locals));
  conds_.push_back({Cond::Kind::macro_call, frames_.size() - 1, 0, 0, name.where});
  ++macro_depth_;
}

void Parser::end_macro() {
  std::vector<std::pair<std::string, Value>> results;
  for (const auto& [parameter, caller] : frames_.back().by_reference)
    if (const auto found = scopes_.back().find(parameter); found != scopes_.back().end())
      results.emplace_back(caller, found->second);
  conds_.pop_back();
  frames_.pop_back();
  scopes_.pop_back();
  --macro_depth_;
  for (auto& [caller, value] : results) assign(caller, std::move(value));
}

void Parser::directive_include(const Token& d) {
  const std::string file = parse_string();
  int depth = 0;
  for (const auto& f : frames_) depth += f.kind == Frame::Kind::include;
  if (depth >= options_.max_include_depth)
    fail(d.where, "#include nested deeper than " + std::to_string(options_.max_include_depth));
  std::vector<std::filesystem::path> candidates{frames_.back().folder / file};
  for (const auto& dir : options_.library_paths) candidates.push_back(dir / file);
  for (const auto& c : candidates) {
    std::error_code ec;
    if (std::filesystem::is_regular_file(c, ec)) {
      push_file(c, Frame::Kind::include, d.where);
      scopes_.emplace_back();
      return;
    }
  }
  fail(d.where,
       "cannot find include file \"" + file + "\" (searched the scene's folder and the library paths)");
}

const Value* Parser::lookup(const std::string& name) const {
  if (!name.empty() && name[0] == '[') {
    const auto found = element_values_.find(name);
    return found == element_values_.end() ? nullptr : &found->second;
  }
  for (auto it = scopes_.rbegin(); it != scopes_.rend(); ++it)
    if (const auto found = it->find(name); found != it->end()) return &found->second;
  return nullptr;
}

void Parser::declare(const std::string& name, Value value, bool local) {
  if (local) {
    scopes_.back()[name] = std::move(value);
    return;
  }
  // #declare of a parameter of the running macro sets the parameter (and, through end_macro, the
  // caller's identifier passed by reference), not a global.
  for (auto f = frames_.rbegin(); f != frames_.rend(); ++f) {
    if (f->kind != Frame::Kind::macro) continue;
    if (std::find(f->parameters.begin(), f->parameters.end(), name) != f->parameters.end() &&
        f->scope < scopes_.size()) {
      scopes_[f->scope][name] = std::move(value);
      return;
    }
    break;
  }
  scopes_.front()[name] = std::move(value);
}

std::vector<ChainStep> Parser::chain() const {
  std::vector<ChainStep> steps;
  for (size_t i = frames_.size(); i-- > 1;) {
    const Frame& f = frames_[i];
    steps.push_back({f.kind == Frame::Kind::macro ? "in macro called from" : "included from", f.call_site});
  }
  return steps;
}

void Parser::fail(const scene::SourceLocation& where, const std::string& text) const {
  throw ParseError(format_diagnostic(texts_, where, "error", text, chain()));
}

void Parser::warn(const scene::SourceLocation& where, const std::string& text) const {
  message(format_diagnostic(texts_, where, "warning", text, chain()));
}

void Parser::message(const std::string& text) const {
  if (options_.message_sink)
    options_.message_sink(text);
  else
    std::cerr << text << '\n';
}

}  // namespace snell::sdl
