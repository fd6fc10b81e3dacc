// The parser's side of --max-memory (memory/budget.hpp): big lists are charged before they are
// allocated, and a charge past the limit becomes a `file:line:col: error:` naming the item.
#include "snell/sdl/parser.hpp"

namespace snell::sdl {

namespace {

/// The scene's budget, made on first use: the caller's (--max-memory) or one of the default size.
const std::shared_ptr<memory::Budget>& budget_of(scene::Scene& scene, const ParseOptions& options) {
  if (!scene.memory_budget)
    scene.memory_budget = options.memory_budget ? options.memory_budget
                                                : std::make_shared<memory::Budget>(memory::default_limit());
  return scene.memory_budget;
}

}  // namespace

memory::Charge Parser::charge_memory(const scene::SourceLocation& where, uint64_t bytes,
                                     std::string_view consumer) {
  try {
    return memory::Charge(budget_of(scene_, options_), bytes, consumer);
  } catch (const memory::BudgetExceeded& e) {
    fail(where, e.what());
  }
}

void Parser::keep_memory(const scene::SourceLocation& where, uint64_t bytes, std::string_view consumer) {
  try {
    budget_of(scene_, options_)->charge(bytes, consumer);
  } catch (const memory::BudgetExceeded& e) {
    fail(where, e.what());
  }
}

void Parser::locate_memory_errors(const std::function<void()>& parse) {
  try {
    parse();
  } catch (const memory::BudgetExceeded& e) {
    fail(raw_peek().where, e.what());
  }
}

}  // namespace snell::sdl
