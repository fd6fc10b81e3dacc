#include "snell/geometry/piece_tree.hpp"

#include <algorithm>
#include <numeric>

namespace snell::geometry {

namespace {

/// Pieces per leaf: a leaf's pieces are tested one by one anyway, and a node test costs about as much.
constexpr uint32_t kLeafPieces = 4;

}  // namespace

PieceTree::PieceTree(std::span<const CurveSegment> pieces) {
  if (pieces.empty()) return;
  order_.resize(pieces.size());
  std::iota(order_.begin(), order_.end(), 0u);
  nodes_.reserve(2 * pieces.size() / kLeafPieces + 1);
  nodes_.emplace_back();
  build(0, 0, static_cast<uint32_t>(pieces.size()), pieces);
}

void PieceTree::build(uint32_t node, uint32_t begin, uint32_t end, std::span<const CurveSegment> pieces) {
  Vec2 lo = pieces[order_[begin]].lo, hi = pieces[order_[begin]].hi;
  for (uint32_t i = begin; i < end; ++i) {
    const CurveSegment& p = pieces[order_[i]];
    lo = {std::min(lo.u, p.lo.u), std::min(lo.v, p.lo.v)};
    hi = {std::max(hi.u, p.hi.u), std::max(hi.v, p.hi.v)};
  }
  nodes_[node].lo = lo;
  nodes_[node].hi = hi;
  if (end - begin <= kLeafPieces) {
    nodes_[node].first = begin;
    nodes_[node].count = end - begin;
    return;
  }
  // Halve at the median centre along the rectangle's longer side.
  const bool along_u = hi.u - lo.u >= hi.v - lo.v;
  const auto centre = [&](uint32_t i) {
    const CurveSegment& p = pieces[i];
    return along_u ? p.lo.u + p.hi.u : p.lo.v + p.hi.v;
  };
  const uint32_t middle = begin + (end - begin) / 2;
  std::nth_element(order_.begin() + begin, order_.begin() + middle, order_.begin() + end,
                   [&](uint32_t a, uint32_t b) { return centre(a) < centre(b); });
  const auto children = static_cast<uint32_t>(nodes_.size());
  nodes_[node].first = children;
  nodes_.emplace_back();
  nodes_.emplace_back();
  build(children, begin, middle, pieces);
  build(children + 1, middle, end, pieces);
}

}  // namespace snell::geometry
