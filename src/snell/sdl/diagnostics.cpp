#include "snell/sdl/diagnostics.hpp"

namespace snell::sdl {

std::string SourceTexts::line(const std::string& file_name, int line) const {
  const auto it = texts_.find(file_name);
  if (it == texts_.end() || line < 1) return {};
  const std::string& text = *it->second;
  size_t start = 0;
  for (int i = 1; i < line; ++i) {
    start = text.find('\n', start);
    if (start == std::string::npos) return {};
    ++start;
  }
  size_t end = text.find('\n', start);
  if (end == std::string::npos) end = text.size();
  std::string result = text.substr(start, end - start);
  if (!result.empty() && result.back() == '\r') result.pop_back();
  return result;
}

std::string format_diagnostic(const SourceTexts& texts, const scene::SourceLocation& where,
                              const std::string& severity, const std::string& message,
                              const std::vector<ChainStep>& chain) {
  std::string out = where.to_string() + ": " + severity + ": " + message;
  if (where.file) {
    const std::string source = texts.line(*where.file, where.line);
    if (!source.empty()) {
      out += "\n" + source + "\n";
      // Keep tabs so that the caret lines up under the column in a terminal.
      for (int i = 1; i < where.column && i - 1 < static_cast<int>(source.size()); ++i)
        out += source[static_cast<size_t>(i - 1)] == '\t' ? '\t' : ' ';
      out += '^';
    }
  }
  for (const auto& step : chain) out += "\nnote: " + step.what + " " + step.where.to_string();
  return out;
}

}  // namespace snell::sdl
