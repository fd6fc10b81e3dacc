#pragma once
#include <string>
#include <vector>

namespace snell::cli {

/// `snell explain SCENE --pixel X,Y ...`: shows how the image is made (docs/explain.md): the ray tree of a
/// pixel as text, JSON or an SVG plan. Returns the exit code; throws UsageError for a bad command line.
int run_explain(const std::vector<std::string>& args);

}  // namespace snell::cli
