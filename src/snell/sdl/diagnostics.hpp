#pragma once
// Messages in the compiler format DESIGN.md asks for: `file:line:col: error: message`, the source line and
// a caret, then `note: included from ...` lines for the include/macro chain.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "snell/scene/source_location.hpp"

namespace snell::sdl {

/// The texts of every file read, so that a message can quote its line.
class SourceTexts {
 public:
  void add(const std::string& file_name, std::shared_ptr<const std::string> text) {
    texts_[file_name] = std::move(text);
  }
  /// Line `line` (1-based) of `file_name`, empty when unknown.
  std::string line(const std::string& file_name, int line) const;

 private:
  std::map<std::string, std::shared_ptr<const std::string>> texts_;
};

/// One step of the chain that led to a message: "included from" or "in macro called from".
struct ChainStep {
  std::string what;
  scene::SourceLocation where;
};

/// `severity` is "error" or "warning"; `chain` lists the include/call sites, innermost first.
std::string format_diagnostic(const SourceTexts& texts, const scene::SourceLocation& where,
                              const std::string& severity, const std::string& message,
                              const std::vector<ChainStep>& chain = {});

/// Thrown below the parser before it knows the include chain (e.g. by the lexer); the parser turns it
/// into a ParseError.
struct LocatedError {
  scene::SourceLocation where;
  std::string message;
};

}  // namespace snell::sdl
