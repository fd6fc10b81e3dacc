#pragma once
#include <memory>
#include <string>

namespace snell::scene {

/// Where something was declared in the scene text (for messages, statistics and `snell explain`).
struct SourceLocation {
  std::shared_ptr<const std::string> file;  // shared: thousands of objects name the same file
  int line = 0;
  int column = 0;

  std::string to_string() const {
    return (file ? *file : std::string("<scene>")) + ":" + std::to_string(line) + ":" +
           std::to_string(column);
  }
};

}  // namespace snell::scene
