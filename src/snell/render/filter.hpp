#pragma once
// Pixel reconstruction filters for the fixed-sample-count mode (--spp): each pixel traces its samples over
// the filter's square support around its centre and weights them by filter(dx) * filter(dy) (a separable
// filter), so pixels stay independent of each other, and of tiles and threads.
#include <optional>
#include <string>
#include <string_view>

namespace snell::render {

class Filter {
 public:
  enum class Kind { box, tent, gaussian, mitchell };
  /// `radius` in pixels (> 0).
  Filter(Kind kind, double radius);
  /// The one-dimensional filter, normalised so its integral over [-radius, radius] is 1.
  double value(double x) const;
  double weight(double dx, double dy) const { return value(dx) * value(dy); }
  double radius() const { return radius_; }
  Kind kind() const { return kind_; }

  /// "box", "tent", "gaussian" or "mitchell", optionally followed by ":RADIUS"; nullopt when unknown or the
  /// radius is not a positive number. Default radii: box 0.5, tent 1, gaussian 1.5, mitchell 2.
  static std::optional<Filter> parse(std::string_view text);

 private:
  Kind kind_;
  double radius_;
  double scale_ = 1;  // normalisation
};

}  // namespace snell::render
