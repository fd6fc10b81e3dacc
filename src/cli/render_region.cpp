// POV-Ray's partial-render switches +SR/+ER/+SC/+EC (Start_Row, End_Row, Start_Column, End_Column): a value
// with a decimal point is a fraction of the image height or width, an integer a 1-based row or column, and
// the end row or column is included (POV-Ray 3.7 reference, "Output Options" / "Partial Output").
#include <cmath>
#include <string>

#include "cli/options.hpp"

namespace snell::cli {

namespace {

/// The 0-based pixel index where a start bound begins or an end bound stops (exclusive).
int pixel_bound(const std::string& flag, const std::string& text, int size, bool is_end) {
  double value = 0;
  try {
    size_t used = 0;
    value = std::stod(text, &used);
    if (used != text.size()) throw std::invalid_argument(text);
  } catch (const std::exception&) {
    throw UsageError("invalid value '" + text + "' for " + flag + " (expected a row/column or a fraction)");
  }
  if (text.find('.') != std::string::npos) {
    if (value < 0 || value > 1)
      throw UsageError(flag + " fraction must lie between 0.0 and 1.0, got " + text);
    return static_cast<int>(std::lround(value * size));
  }
  if (value < 1 || value > size)
    throw UsageError(flag + " must lie between 1 and " + std::to_string(size) + ", got " + text);
  const int pixel = static_cast<int>(value);
  return is_end ? pixel : pixel - 1;
}

}  // namespace

PixelBounds render_region(const CliOptions& o) {
  PixelBounds b{0, 0, o.width, o.height};
  if (!o.start_col.empty()) b.x0 = pixel_bound("+SC", o.start_col, o.width, false);
  if (!o.end_col.empty()) b.x1 = pixel_bound("+EC", o.end_col, o.width, true);
  if (!o.start_row.empty()) b.y0 = pixel_bound("+SR", o.start_row, o.height, false);
  if (!o.end_row.empty()) b.y1 = pixel_bound("+ER", o.end_row, o.height, true);
  if (b.x1 <= b.x0 || b.y1 <= b.y0)
    throw UsageError("the partial-render bounds (+SR/+ER/+SC/+EC) select no pixels");
  return b;
}

}  // namespace snell::cli
