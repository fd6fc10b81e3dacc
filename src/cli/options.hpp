#pragma once
// Everything the `snell` command was asked to do, whichever syntax it came in (snell's own
// `snell render ...` or POV-Ray's `+I... +W... +A...`).
#include <filesystem>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace snell::cli {

/// A bad command line (exit code 2). The message is one line.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct CliOptions {
  std::filesystem::path input;
  std::filesystem::path output;  // empty: the scene's name with .png, in the current folder
  int width = 800;               // POV-Ray 3.7's defaults without an ini file
  int height = 600;
  bool antialias = false;
  double aa_threshold = 0.3;
  double aa_gamma = 2.5;  // POV-Ray +AG / Antialias_Gamma
  int aa_depth = 3;
  bool jitter = true;  // POV-Ray 3.7 jitters supersamples unless -J (view.cpp: Jitter defaults on)
  double jitter_amount = 1.0;
  int aa_method = 1;              // POV-Ray +AM1 / +AM2
  int samples_per_pixel = 0;      // --spp N (0: POV-Ray anti-aliasing)
  std::string sampler = "sobol";  // --sampler
  std::string filter = "box";     // --filter NAME[:RADIUS]
  int threads = 0;
  std::string integrator = "whitted";  // whitted (POV-Ray compatible) or path
  std::string accel = "auto";          // auto: embree when built, else brute force
  int bits = 8;
  /// Output format by extension, used when the output name has none (POV-Ray +FN/+FE/+FH).
  std::string extension = ".png";
  bool quiet = false;
  bool stats = false;
  /// Parse and build the scene, print a summary, render nothing (`--parse-only`).
  bool parse_only = false;
  /// `+D` / `--display`: show the render in a window (src/cli/preview/); `+P`: keep it open until a key.
  bool display = false;
  bool pause_when_done = false;
  /// Hidden test option `--display-snapshot FILE`: the window's pixels, read back at the end, as PNG.
  std::filesystem::path display_snapshot;
  /// `--watch`: render again whenever the scene or a file it reads changes (src/cli/watch.cpp).
  bool watch = false;
  /// True once +W/+H/Width=/Height=/-w/-h gave a size (--watch renders at a preview size otherwise).
  bool size_given = false;
  /// Called with every file the scene parser reads (the scene, includes, images, fonts, #fopen).
  std::function<void(const std::filesystem::path&)> on_file_read;
  /// Partial render (POV-Ray +SR +ER +SC +EC), as written: "0.5" is a fraction of the image, "120" a
  /// 1-based pixel row or column (end inclusive). Empty: the image's edge.
  std::string start_row, end_row, start_col, end_col;
  /// `+C` / `--continue`: finish the render whose resume file lies beside the output.
  bool resume = false;
  /// `--checkpoint S`: write the resume file every S seconds while rendering (0: only when interrupted).
  double checkpoint_seconds = 0;
  std::vector<std::filesystem::path> library_paths;
  std::map<std::string, double> declares;
  /// Animation range (+KFI +KFF +KI +KF +KC, `--frames A-B`, ini Initial_Frame...) and the subset of it
  /// rendered (+SF +EF, Subset_Start_Frame...; below 0: the whole range; between 0 and 1: a fraction, as
  /// in POV-Ray). Every frame of the subset is rendered (cli/animation.hpp).
  int initial_frame = 1;
  int final_frame = 1;
  double initial_clock = 0;
  double final_clock = 1;
  double subset_start = -1;
  double subset_end = -1;
  bool cyclic = false;
  /// The frame being rendered (set per frame by the animation loop; 0 for a still).
  int frame = 0;
  /// `--video out.mp4`: join the frames with ffmpeg when it is installed; `--fps`: its frame rate.
  std::filesystem::path video;
  double fps = 24;
  /// `--max-loop N`: the most iterations one #while or #for may run before the scene is stopped.
  long max_loop = 10'000'000;
  /// `--max-memory SIZE` ("2G", "512M"): what the scene's big arrays may take (memory/budget.hpp); empty:
  /// three quarters of physical memory.
  std::string max_memory;
  /// Warnings found while reading the command line (unknown or unsupported flags), printed unless quiet.
  std::vector<std::string> warnings;
};

/// POV-Ray style: `+Iscene.pov +Oout.png +W640 +H480 +A0.3 +R3 +J +Ldir -D +WT4`, plus snell's
/// `--quiet`, `--stats`, `--threads N`, `--accel NAME`. Known but unsupported POV-Ray switches become
/// warnings; unknown ones throw UsageError.
CliOptions parse_pov_arguments(const std::vector<std::string>& args);

/// Replaces each ini file among `args` (`scene.ini`, `+Iscene.ini`) by its lines. Throws UsageError.
std::vector<std::string> expand_ini_files(const std::vector<std::string>& args, int depth = 0);

/// Applies one ini-style `Key=Value` option (also accepted on the command line); false when unknown.
bool apply_ini_option(CliOptions& options, const std::string& key, const std::string& value);

/// `A-B` or `A` (frames of `--frames`, `--subset`): sets `first` and `last`. Throws UsageError.
void parse_frame_range(const std::string& flag, const std::string& text, int& first, int& last);

/// Checks values common to both syntaxes and fills in the default output name. Throws UsageError.
void validate(CliOptions& options);

/// The pixels +SR/+ER/+SC/+EC select, x0 <= x < x1, y0 <= y < y1 (the whole image without them).
/// Throws UsageError for a bound that is not a number, lies outside the image or leaves nothing.
struct PixelBounds {
  int x0, y0, x1, y1;
};
PixelBounds render_region(const CliOptions& options);

}  // namespace snell::cli
