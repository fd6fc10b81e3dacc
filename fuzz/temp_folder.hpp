#pragma once
// A private temporary folder per fuzz process (made once, on first use): the parse target's scene folder
// and the file targets' input files live there, so nothing a fuzzed input names lands elsewhere.
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace snell::fuzz {

inline std::filesystem::path make_private_folder(const std::string& prefix) {
  std::string pattern = (std::filesystem::temp_directory_path() / (prefix + "-XXXXXX")).string();
  if (!mkdtemp(pattern.data())) std::abort();
  return std::filesystem::path(pattern);
}

}  // namespace snell::fuzz
