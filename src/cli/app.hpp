#pragma once
#include <string>
#include <vector>

namespace snell::cli {

/// Exit codes (docs/cli.md).
enum ExitCode : int { kOk = 0, kSceneError = 1, kUsageError = 2, kIoError = 3, kInterrupted = 130 };

/// The whole program: reads `args` (without the program name) and returns the exit code.
int run_app(const std::vector<std::string>& args);

}  // namespace snell::cli
