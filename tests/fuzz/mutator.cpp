#include "mutator.hpp"

#include <fstream>

namespace snell::fuzz::test {

std::string Mutator::mutate(std::string input) {
  const size_t count = 1 + below(4);
  for (size_t i = 0; i < count; ++i) {
    switch (below(12)) {
      case 0:
      case 1:
      case 2:
        flip_byte(input);
        break;
      case 3:
      case 4:
      case 5:
      case 6:
        splice_token(input);
        break;
      case 7:
      case 8:
        cut_range(input);
        break;
      case 9:
        duplicate_range(input);
        break;
      case 10:
        truncate(input);
        break;
      default:
        nest_deeply(input);
        break;
    }
  }
  return input;
}

void Mutator::flip_byte(std::string& s) {
  if (s.empty()) return;
  s[below(s.size())] ^= static_cast<char>(1u << below(8));
}

void Mutator::splice_token(std::string& s) {
  if (dictionary_.empty()) return;
  const std::string& token = dictionary_[below(dictionary_.size())];
  s.insert(below(s.size() + 1), " " + token + " ");
}

void Mutator::cut_range(std::string& s) {
  if (s.empty()) return;
  const size_t start = below(s.size());
  s.erase(start, 1 + below(std::min<size_t>(64, s.size() - start)));
}

void Mutator::duplicate_range(std::string& s) {
  if (s.empty()) return;
  const size_t start = below(s.size());
  const size_t length = 1 + below(std::min<size_t>(200, s.size() - start));
  s.insert(below(s.size() + 1), s.substr(start, length));
}

void Mutator::truncate(std::string& s) {
  s.resize(below(s.size() + 1));
}

void Mutator::nest_deeply(std::string& s) {
  // Openers that recurse in the parser: expressions, vectors, objects, blocks, comments, directives.
  static const char* const openers[] = {"(",   "<",        "-",          "union { ",    "pigment { ",
                                        "/* ", "#if (1) ", "texture { ", "array[1] { ", "#macro M() M() "};
  const std::string opener = openers[below(std::size(openers))];
  const size_t depth = 1 + below(2000);
  std::string nest;
  nest.reserve(opener.size() * depth);
  for (size_t i = 0; i < depth; ++i) nest += opener;
  s.insert(below(s.size() + 1), nest);
}

std::vector<std::string> read_dictionary(const std::string& path) {
  std::vector<std::string> words;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    const size_t open = line.find('"');
    if (line.empty() || line[0] == '#' || open == std::string::npos || line.back() != '"') continue;
    std::string word;
    for (size_t i = open + 1; i + 1 < line.size(); ++i) {
      if (line[i] == '\\' && i + 2 < line.size()) ++i;
      word += line[i];
    }
    words.push_back(word);
  }
  return words;
}

}  // namespace snell::fuzz::test
