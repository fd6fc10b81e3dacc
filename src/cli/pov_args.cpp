#include <algorithm>
#include <cctype>
#include <charconv>
#include <string>

#include "cli/options.hpp"

namespace snell::cli {

namespace {

std::string upper(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::toupper(c); });
  return s;
}

int parse_int(const std::string& flag, const std::string& text) {
  int v = 0;
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, v);
  if (text.empty() || ec != std::errc() || ptr != end)
    throw UsageError("invalid value '" + text + "' for " + flag + " (expected an integer)");
  return v;
}

double parse_double(const std::string& flag, const std::string& text) {
  try {
    size_t used = 0;
    const double v = std::stod(text, &used);
    if (used == text.size()) return v;
  } catch (const std::exception&) {
  }
  throw UsageError("invalid value '" + text + "' for " + flag + " (expected a number)");
}

bool starts_with(const std::string& s, const std::string& prefix) {
  return s.rfind(prefix, 0) == 0;
}

/// POV-Ray switches that snell knows but does not implement: accepted with a warning.
constexpr const char* kUnsupported[] = {"Q",  "AG", "UA", "GA", "GD", "GF", "GR",  "GS", "GW", "K", "UV",
                                        "UR", "UF", "UD", "UO", "MB", "MV", "RVP", "HT", "HN", "HI"};
/// Known switches without an effect on a batch render: accepted silently.
constexpr const char* kIgnored[] = {"V", "X", "GP"};

/// POV-Ray stops on a switch it does not know ("Failed to parse command-line option"); so does snell,
/// pointing at the snell form for the -o/-w/-h style flags people type by habit.
UsageError unknown_option(const std::string& arg) {
  return UsageError(
      "unknown option '" + arg +
      "' (POV-Ray style: +Iscene.pov +Oout.png +W640 +H480; snell style: snell render scene.pov "
      "-o out.png -w 640 -h 480; see snell --help)");
}

}  // namespace

CliOptions parse_pov_arguments(const std::vector<std::string>& command_line) {
  const std::vector<std::string> args = expand_ini_files(command_line);
  CliOptions o;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    auto next_value = [&](const std::string& flag) -> std::string {
      if (i + 1 >= args.size()) throw UsageError(flag + " needs a value");
      return args[++i];
    };
    if (starts_with(arg, "--")) {
      std::string name = arg, value;
      const auto eq = arg.find('=');
      if (eq != std::string::npos) {
        name = arg.substr(0, eq);
        value = arg.substr(eq + 1);
      }
      if (name == "--quiet") {
        o.quiet = true;
      } else if (name == "--stats") {
        o.stats = true;
      } else if (name == "--display") {
        o.display = true;
      } else if (name == "--display-snapshot") {
        o.display_snapshot = eq == std::string::npos ? next_value(name) : value;
      } else if (name == "--watch") {
        o.watch = true;
      } else if (name == "--parse-only") {
        o.parse_only = true;
      } else if (name == "--threads") {
        o.threads = parse_int(name, eq == std::string::npos ? next_value(name) : value);
      } else if (name == "--continue") {
        o.resume = true;
      } else if (name == "--checkpoint") {
        o.checkpoint_seconds = parse_double(name, eq == std::string::npos ? next_value(name) : value);
      } else if (name == "--max-loop") {
        o.max_loop = parse_int(name, eq == std::string::npos ? next_value(name) : value);
        if (o.max_loop < 1) throw UsageError("--max-loop needs a positive number");
      } else if (name == "--frames") {
        parse_frame_range(name, eq == std::string::npos ? next_value(name) : value, o.initial_frame,
                          o.final_frame);
      } else if (name == "--video") {
        o.video = eq == std::string::npos ? next_value(name) : value;
      } else if (name == "--fps") {
        o.fps = parse_double(name, eq == std::string::npos ? next_value(name) : value);
      } else if (name == "--max-memory") {
        o.max_memory = eq == std::string::npos ? next_value(name) : value;
      } else if (name == "--accel") {
        o.accel = eq == std::string::npos ? next_value(name) : value;
      } else if (name == "--spp") {
        o.samples_per_pixel = parse_int(name, eq == std::string::npos ? next_value(name) : value);
      } else if (name == "--sampler") {
        o.sampler = eq == std::string::npos ? next_value(name) : value;
      } else if (name == "--filter") {
        o.filter = eq == std::string::npos ? next_value(name) : value;
      } else {
        throw unknown_option(arg);
      }
      continue;
    }
    if (arg.size() < 2 || (arg[0] != '+' && arg[0] != '-')) {
      const auto eq = arg.find('=');
      if (eq != std::string::npos && apply_ini_option(o, arg.substr(0, eq), arg.substr(eq + 1))) {
        // Width=, Declare=, Initial_Frame=...: ini-style options, from an ini file or typed
      } else if (eq != std::string::npos) {
        o.warnings.push_back("ini-style option '" + arg + "' is not supported; ignored");
      } else if (o.input.empty()) {
        o.input = arg;
      } else {
        throw UsageError("extra argument '" + arg + "': the scene is already '" + o.input.string() +
                         "' (the output file is given as +O" + arg + ")");
      }
      continue;
    }
    const bool on = arg[0] == '+';
    const std::string body = arg.substr(1);
    const std::string key = upper(body);
    auto rest_after = [&](size_t n) { return body.substr(n); };

    if (key[0] == 'I' && key.size() > 1) {
      o.input = rest_after(1);
    } else if (key[0] == 'O' && key.size() > 1) {
      o.output = rest_after(1);
    } else if (key[0] == 'L' && key.size() > 1) {
      o.library_paths.emplace_back(rest_after(1));
    } else if (key == "C") {
      o.resume = on;
    } else if (starts_with(key, "SR") && key.size() > 2) {
      o.start_row = rest_after(2);
    } else if (starts_with(key, "ER") && key.size() > 2) {
      o.end_row = rest_after(2);
    } else if (starts_with(key, "SC") && key.size() > 2) {
      o.start_col = rest_after(2);
    } else if (starts_with(key, "EC") && key.size() > 2) {
      o.end_col = rest_after(2);
    } else if (key == "KC") {
      o.cyclic = on;
    } else if (starts_with(key, "KFI")) {
      o.initial_frame = parse_int(arg, rest_after(3));
    } else if (starts_with(key, "KFF")) {
      o.final_frame = parse_int(arg, rest_after(3));
    } else if (starts_with(key, "KI") && key.size() > 2) {
      o.initial_clock = parse_double(arg, rest_after(2));
    } else if (starts_with(key, "KF") && key.size() > 2) {
      o.final_clock = parse_double(arg, rest_after(2));
    } else if (starts_with(key, "SF") && key.size() > 2) {
      o.subset_start = parse_double(arg, rest_after(2));
    } else if (starts_with(key, "EF") && key.size() > 2) {
      o.subset_end = parse_double(arg, rest_after(2));
    } else if (starts_with(key, "WT")) {
      o.threads = parse_int(arg, rest_after(2));
    } else if (key[0] == 'W' && key.size() > 1) {
      o.width = parse_int(arg, rest_after(1));
      o.size_given = true;
    } else if (key[0] == 'H' && key.size() > 1 && !starts_with(key, "HT") && !starts_with(key, "HN") &&
               !starts_with(key, "HI")) {
      o.height = parse_int(arg, rest_after(1));
      o.size_given = true;
    } else if (key == "A" || (key[0] == 'A' && key.size() > 1 &&
                              (std::isdigit(static_cast<unsigned char>(key[1])) || key[1] == '.'))) {
      o.antialias = on;
      if (key.size() > 1) o.aa_threshold = parse_double(arg, rest_after(1));
    } else if (starts_with(key, "AG") && key.size() > 2) {
      o.aa_gamma = parse_double(arg, rest_after(2));
    } else if (starts_with(key, "AM")) {
      const int method = key.size() > 2 ? parse_int(arg, rest_after(2)) : 1;
      if (method == 1 || method == 2)
        o.aa_method = method;
      else
        o.warnings.push_back("anti-aliasing method " + std::to_string(method) +
                             " is not supported; using method 1");
    } else if (key[0] == 'R' && key.size() > 1 && std::isdigit(static_cast<unsigned char>(key[1]))) {
      o.aa_depth = parse_int(arg, rest_after(1));
    } else if (key == "J" || (key[0] == 'J' && key.size() > 1 &&
                              (std::isdigit(static_cast<unsigned char>(key[1])) || key[1] == '.'))) {
      o.jitter = on;
      if (key.size() > 1) o.jitter_amount = parse_double(arg, rest_after(1));
    } else if ((key[0] == 'D' || key[0] == 'P') &&
               (key.size() == 1 || std::isdigit(static_cast<unsigned char>(key[1])))) {
      // +D display (POV-Ray's +D0 style palette digit is accepted and has no effect), +P pause when done
      (key[0] == 'D' ? o.display : o.pause_when_done) = on;
    } else if (key[0] == 'F' && (key.size() == 1 || std::isalpha(static_cast<unsigned char>(key[1])))) {
      const std::string fmt = key.substr(1);
      if (fmt.empty() || fmt == "N" || fmt == "N8") {
        o.bits = 8;
        o.extension = ".png";
      } else if (fmt == "N16") {
        o.bits = 16;
        o.extension = ".png";
      } else if (fmt == "E")
        o.extension = ".exr";
      else if (fmt == "H")
        o.extension = ".hdr";
      else
        o.warnings.push_back("output format '" + arg + "' is not supported; writing PNG");
    } else if (std::find_if(std::begin(kIgnored), std::end(kIgnored), [&](const char* k) {
                 return starts_with(key, k) &&
                        (key.size() == std::string(k).size() ||
                         std::isdigit(static_cast<unsigned char>(key[std::string(k).size()])));
               }) != std::end(kIgnored)) {
      // display, pause, verbose...: nothing to do in a batch renderer
    } else if (std::find_if(std::begin(kUnsupported), std::end(kUnsupported),
                            [&](const char* k) { return starts_with(key, k); }) != std::end(kUnsupported)) {
      o.warnings.push_back("option '" + arg + "' is not supported yet; ignored");
    } else {
      throw unknown_option(arg);
    }
  }
  return o;
}

}  // namespace snell::cli
