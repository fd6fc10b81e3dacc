// Parallel rewriting of module strings (ABoP 1990, ch. 1 and 1.10).
#include "snell/procedural/lsystem.hpp"

#include <array>
#include <cctype>
#include <memory>
#include <optional>

#include "snell/math/pcg32.hpp"

namespace snell::procedural {

std::span<const double> ModuleString::parameters(std::size_t i) const {
  if (offsets_.empty()) return {};
  return std::span<const double>(params_).subspan(offsets_[i], offsets_[i + 1] - offsets_[i]);
}

void ModuleString::push_back(char symbol, std::span<const double> parameters) {
  if (!parameters.empty() && offsets_.empty()) offsets_.assign(symbols_.size() + 1, 0);
  symbols_.push_back(symbol);
  if (offsets_.empty()) return;
  params_.insert(params_.end(), parameters.begin(), parameters.end());
  offsets_.push_back(static_cast<std::uint32_t>(params_.size()));
}

std::size_t ModuleString::bytes() const {
  return symbols_.capacity() + offsets_.capacity() * sizeof(std::uint32_t) +
         params_.capacity() * sizeof(double);
}

namespace {

std::string without_spaces(std::string_view text) {
  std::string out;
  for (const char c : text)
    if (!std::isspace(static_cast<unsigned char>(c))) out.push_back(c);
  return out;
}

/// Splits "a,b(c,d),e" at the commas outside parentheses.
std::vector<std::string> split_arguments(std::string_view text) {
  std::vector<std::string> parts(1);
  int depth = 0;
  for (const char c : text) {
    if (c == ',' && depth == 0) {
      parts.emplace_back();
      continue;
    }
    depth += c == '(' ? 1 : (c == ')' ? -1 : 0);
    parts.back().push_back(c);
  }
  return parts;
}

/// One module of a successor or axiom: its symbol and the text of each argument.
struct ModuleText {
  char symbol;
  std::vector<std::string> arguments;
};

std::vector<ModuleText> split_modules(std::string_view text_in, std::string_view what) {
  const std::string text = without_spaces(text_in);
  std::vector<ModuleText> modules;
  for (std::size_t i = 0; i < text.size();) {
    const char symbol = text[i++];
    if (symbol == '(' || symbol == ')' || symbol == ',')
      throw LSystemError(std::string(what) + " \"" + std::string(text_in) + "\": unexpected '" + symbol +
                         "'");
    ModuleText m{symbol, {}};
    if (i < text.size() && text[i] == '(') {
      int depth = 0;
      const std::size_t open = i;
      for (; i < text.size(); ++i) {
        depth += text[i] == '(' ? 1 : (text[i] == ')' ? -1 : 0);
        if (depth == 0) break;
      }
      if (i >= text.size())
        throw LSystemError(std::string(what) + " \"" + std::string(text_in) + "\": missing ')'");
      m.arguments = split_arguments(std::string_view(text).substr(open + 1, i - open - 1));
      ++i;
    }
    modules.push_back(std::move(m));
  }
  return modules;
}

struct CompiledModule {
  char symbol;
  std::vector<Expression> arguments;
};

struct CompiledRule {
  char symbol = 0;
  std::size_t arity = 0;
  std::optional<Expression> condition;
  std::vector<CompiledModule> successor;
  double probability = 1;
};

CompiledRule compile(const LSystemRule& rule) {
  CompiledRule out;
  out.probability = rule.probability;
  if (!(rule.probability > 0)) throw LSystemError("a rule's probability must be positive");
  std::string head = without_spaces(rule.predecessor);
  std::string condition;
  if (const auto colon = head.find(':'); colon != std::string::npos) {
    condition = head.substr(colon + 1);
    head.resize(colon);
  }
  const auto modules = split_modules(head, "predecessor");
  if (modules.size() != 1)
    throw LSystemError("predecessor \"" + rule.predecessor + "\" must be one module, such as A or A(l,w)");
  out.symbol = modules[0].symbol;
  std::vector<std::string> names;
  if (!modules[0].arguments.empty()) {
    for (const std::string& name : modules[0].arguments) {
      const bool ok = !name.empty() && std::isalpha(static_cast<unsigned char>(name[0]));
      if (!ok) throw LSystemError("predecessor \"" + rule.predecessor + "\": parameters must be names");
      names.push_back(name);
    }
  }
  out.arity = names.size();
  if (!condition.empty()) out.condition.emplace(condition, names);
  for (const ModuleText& m : split_modules(rule.successor, "successor")) {
    CompiledModule cm{m.symbol, {}};
    for (const std::string& argument : m.arguments) cm.arguments.emplace_back(argument, names);
    out.successor.push_back(std::move(cm));
  }
  return out;
}

}  // namespace

ModuleString parse_modules(std::string_view text) {
  ModuleString out;
  for (const ModuleText& m : split_modules(text, "axiom")) {
    std::vector<double> values;
    for (const std::string& argument : m.arguments) values.push_back(Expression(argument, {}).evaluate({}));
    out.push_back(m.symbol, values);
  }
  return out;
}

ModuleString generate_lsystem(const LSystemSettings& settings) {
  if (settings.iterations < 0) throw LSystemError("iterations must not be negative");
  std::vector<CompiledRule> rules;
  for (const LSystemRule& rule : settings.rules) rules.push_back(compile(rule));
  // The rules of each symbol, so a module finds its candidates without scanning every rule.
  std::array<std::vector<const CompiledRule*>, 256> by_symbol;
  for (const CompiledRule& r : rules) by_symbol[static_cast<unsigned char>(r.symbol)].push_back(&r);

  math::Pcg32 random(settings.seed, 0x4c53595354454dULL);
  ModuleString current = parse_modules(settings.axiom);
  std::vector<const CompiledRule*> matching;
  std::vector<double> values;
  // Bounds on memory (parameters) and time (modules rewritten over all iterations, as a string that stops
  // growing may still be rewritten up to 1000 times).
  const std::size_t max_parameters = 2 * settings.max_length, max_work = 10 * settings.max_length;
  std::size_t work = 0;
  for (int step = 0; step < settings.iterations; ++step) {
    if ((work += current.size()) > max_work)
      throw LSystemError("the L-system rewrites more than " + std::to_string(max_work) +
                         " modules over its iterations (10 x max_length); use fewer iterations");
    ModuleString next;
    for (std::size_t i = 0; i < current.size(); ++i) {
      const char symbol = current.symbol(i);
      const std::span<const double> params = current.parameters(i);
      matching.clear();
      double total = 0;
      for (const CompiledRule* r : by_symbol[static_cast<unsigned char>(symbol)])
        if (r->arity == params.size() && (!r->condition || r->condition->evaluate(params) != 0)) {
          matching.push_back(r);
          total += r->probability;
        }
      const CompiledRule* chosen = matching.empty() ? nullptr : matching.front();
      if (matching.size() > 1) {
        // Stochastic choice in proportion to the probabilities (ABoP 1.7); one draw per rewritten module
        // keeps the result a function of the seed alone.
        double pick = random.next_double() * total;
        for (const CompiledRule* r : matching) {
          chosen = r;
          if ((pick -= r->probability) < 0) break;
        }
      }
      if (!chosen) {
        next.push_back(symbol, params);
      } else {
        for (const CompiledModule& m : chosen->successor) {
          values.clear();
          for (const Expression& e : m.arguments) values.push_back(e.evaluate(params));
          next.push_back(m.symbol, values);
        }
      }
      if (next.size() > settings.max_length || next.parameter_count() > max_parameters)
        throw LSystemError("the L-system string passes " + std::to_string(settings.max_length) +
                           " modules (or twice as many parameters) at iteration " + std::to_string(step + 1) +
                           " of " + std::to_string(settings.iterations) +
                           "; use fewer iterations or raise max_length");
    }
    current = std::move(next);
  }
  return current;
}

}  // namespace snell::procedural
