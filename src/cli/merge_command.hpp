#pragma once
#include <string>
#include <vector>

namespace snell::cli {

/// `snell merge part... -o out`: joins partial renders (+SR/+ER/+SC/+EC, or several ranks' or farm jobs'
/// parts) into one image by their alpha coverage. Returns the exit code; throws UsageError or ImageIoError.
int run_merge(const std::vector<std::string>& args);

}  // namespace snell::cli
