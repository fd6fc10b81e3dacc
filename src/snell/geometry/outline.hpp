#pragma once
// A 2D region bounded by curve pieces, filled by the even-odd rule: the cross-section of prisms and
// glyphs, the profile of lathes and the area of polygons. Sub-outlines may nest (holes) and need no
// particular orientation.
#include <algorithm>
#include <cmath>
#include <vector>

#include "snell/geometry/curve_segment.hpp"
#include "snell/geometry/piece_tree.hpp"

namespace snell::geometry {

/// Roots are searched this far beyond a piece's parameter range, so that a crossing exactly at the joint
/// of two pieces is not lost to rounding on both sides; `drop_joint_duplicates` removes the double.
inline constexpr double kJointSlack = 1e-9;

/// Sorts crossings (each with a `t`; `piece_of` gives its piece, negative for caps) by t and drops a
/// crossing that repeats the previous one of another piece at a joint, so that CSG sees each surface
/// crossing once.
template <typename Crossing, typename PieceOf>
void sort_and_drop_joint_duplicates(std::vector<Crossing>& crossings, PieceOf piece_of) {
  std::sort(crossings.begin(), crossings.end(),
            [](const Crossing& a, const Crossing& b) { return a.t < b.t; });
  size_t kept = 0;
  for (size_t i = 0; i < crossings.size(); ++i) {
    if (kept > 0) {
      const Crossing& last = crossings[kept - 1];
      const long a = piece_of(last), b = piece_of(crossings[i]);
      if (a >= 0 && b >= 0 && a != b && std::fabs(crossings[i].t - last.t) <= 1e-9 * (1 + std::fabs(last.t)))
        continue;
    }
    crossings[kept++] = crossings[i];
  }
  crossings.resize(kept);
}

class Outline {
 public:
  explicit Outline(std::vector<CurveSegment> pieces);

  const std::vector<CurveSegment>& pieces() const { return pieces_; }
  Vec2 lo() const { return lo_; }
  Vec2 hi() const { return hi_; }

  /// Even-odd rule: whether a half-line from q towards +u crosses the boundary an odd number of times.
  bool contains(Vec2 q) const;

  /// Calls f(piece index, s) for every crossing of the line n . q + k = 0 with a piece, s in [0, 1] (with
  /// kJointSlack: a crossing at a joint may come twice).
  /// The crossings of piece `i` with the line n . q + k = 0 into `roots` (at most 3); their count.
  int piece_crossings(size_t i, Vec2 n, double k, double* roots) const {
    return crossings(pieces_[i], n, k, roots);
  }

  /// Calls f(piece index) for the pieces whose rectangles may meet the part of the line n . q + k = 0
  /// within the rectangle [lo, hi] (PieceTree::for_each_near), in no particular order.
  template <typename F>
  void for_each_piece_near(Vec2 lo, Vec2 hi, Vec2 n, double k, F&& f) const {
    tree_.for_each_near(lo, hi, n, k, f);
  }

  template <typename F>
  void for_each_crossing(Vec2 n, double k, F&& f) const {
    double roots[3];
    for (size_t i = 0; i < pieces_.size(); ++i) {
      if (!pieces_[i].line_may_cross(n, k)) continue;
      const int count = crossings(pieces_[i], n, k, roots);
      for (int r = 0; r < count; ++r) f(i, roots[r]);
    }
  }

 private:
  static int crossings(const CurveSegment& piece, Vec2 n, double k, double* roots);

  std::vector<CurveSegment> pieces_;
  Vec2 lo_, hi_;
  PieceTree tree_;
};

}  // namespace snell::geometry
