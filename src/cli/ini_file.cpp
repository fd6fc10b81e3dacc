// POV-Ray `.ini` files (POV-Ray 3.7 reference, "INI File Options"): `Key=Value` lines, `;` comments,
// `[Section]` headers and command-line switches (`+W200`). An ini file given on the command line is
// replaced by its lines, so a switch after it overrides it as in POV-Ray.
#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>
#include <string>

#include "cli/options.hpp"

namespace snell::cli {

namespace {

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t\r\n") - first + 1);
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

bool is_ini_name(const std::string& arg) {
  return arg.size() > 4 && lower(arg.substr(arg.size() - 4)) == ".ini";
}

/// Paths in an ini file are relative to the ini file's folder, so `snell dir/scene.ini` works from
/// anywhere (POV-Ray resolves them against its current folder, which is the ini's in practice).
std::string relative_to(const std::filesystem::path& folder, const std::string& value) {
  const std::filesystem::path p(value);
  return p.is_absolute() || folder.empty() ? value : (folder / p).string();
}

bool truth(const std::string& flag, const std::string& value) {
  const std::string v = lower(value);
  if (v == "on" || v == "true" || v == "yes" || v == "1") return true;
  if (v == "off" || v == "false" || v == "no" || v == "0") return false;
  throw UsageError("invalid value '" + value + "' for " + flag + " (expected on or off)");
}

double number(const std::string& flag, const std::string& value) {
  try {
    size_t used = 0;
    const double v = std::stod(value, &used);
    if (trim(value.substr(used)).empty()) return v;
  } catch (const std::exception&) {
  }
  throw UsageError("invalid value '" + value + "' for " + flag + " (expected a number)");
}

}  // namespace

std::vector<std::string> expand_ini_files(const std::vector<std::string>& args, int depth) {
  if (depth > 8) throw UsageError("ini files include each other more than 8 levels deep");
  std::vector<std::string> expanded;
  for (const std::string& arg : args) {
    std::string name;
    if (is_ini_name(arg) && arg[0] != '-') name = arg[0] == '+' && arg.size() > 2 ? arg.substr(2) : arg;
    if (name.empty() || (arg[0] == '+' && std::toupper(static_cast<unsigned char>(arg[1])) != 'I')) {
      expanded.push_back(arg);
      continue;
    }
    std::ifstream in(name);
    if (!in) throw UsageError("cannot read ini file '" + name + "'");
    const std::filesystem::path folder = std::filesystem::path(name).parent_path();
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) {
      line = trim(line.substr(0, line.find(';')));
      if (line.empty() || line[0] == '[') continue;  // comments and [Section] headers
      const auto eq = line.find('=');
      if (eq != std::string::npos && line[0] != '+' && line[0] != '-') {
        const std::string key = lower(trim(line.substr(0, eq)));
        const std::string value = trim(line.substr(eq + 1));
        if (key == "input_file_name" || key == "library_path")
          line = trim(line.substr(0, eq)) + "=" + relative_to(folder, value);
        else
          line = trim(line.substr(0, eq)) + "=" + value;
      }
      if (line[0] == '+' || line[0] == '-') {
        // A switch line may hold several switches and options: `+KF0.5 +KFF20 Declare=A=1`.
        std::istringstream words(line);
        for (std::string word; words >> word;) lines.push_back(word);
      } else {
        lines.push_back(line);
      }
    }
    const auto inner = expand_ini_files(lines, depth + 1);
    expanded.insert(expanded.end(), inner.begin(), inner.end());
  }
  return expanded;
}

bool apply_ini_option(CliOptions& o, const std::string& key_as_written, const std::string& value) {
  const std::string key = lower(key_as_written);
  if (key == "input_file_name") {
    o.input = value;
  } else if (key == "output_file_name") {
    o.output = value;
  } else if (key == "width") {
    o.width = static_cast<int>(number(key_as_written, value));
    o.size_given = true;
  } else if (key == "height") {
    o.height = static_cast<int>(number(key_as_written, value));
    o.size_given = true;
  } else if (key == "display") {
    o.display = truth(key_as_written, value);
  } else if (key == "pause_when_done") {
    o.pause_when_done = truth(key_as_written, value);
  } else if (key == "antialias") {
    o.antialias = truth(key_as_written, value);
  } else if (key == "antialias_threshold") {
    o.aa_threshold = number(key_as_written, value);
  } else if (key == "antialias_gamma") {
    o.aa_gamma = number(key_as_written, value);
  } else if (key == "antialias_depth") {
    o.aa_depth = static_cast<int>(number(key_as_written, value));
  } else if (key == "sampling_method") {
    o.aa_method = static_cast<int>(number(key_as_written, value)) == 2 ? 2 : 1;
  } else if (key == "jitter") {
    o.jitter = truth(key_as_written, value);
  } else if (key == "library_path") {
    o.library_paths.emplace_back(value);
  } else if (key == "initial_frame") {
    o.initial_frame = static_cast<int>(number(key_as_written, value));
  } else if (key == "final_frame") {
    o.final_frame = static_cast<int>(number(key_as_written, value));
  } else if (key == "initial_clock") {
    o.initial_clock = number(key_as_written, value);
  } else if (key == "final_clock") {
    o.final_clock = number(key_as_written, value);
  } else if (key == "cyclic_animation") {
    o.cyclic = truth(key_as_written, value);
  } else if (key == "subset_start_frame") {
    o.subset_start = number(key_as_written, value);
  } else if (key == "subset_end_frame") {
    o.subset_end = number(key_as_written, value);
  } else if (key == "declare") {
    const auto eq = value.find('=');
    if (eq == std::string::npos || eq == 0) throw UsageError("Declare needs NAME=value, got '" + value + "'");
    o.declares[value.substr(0, eq)] = number("Declare", value.substr(eq + 1));
  } else {
    return false;
  }
  return true;
}

}  // namespace snell::cli
