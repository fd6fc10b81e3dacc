// The collapse of a binary BVH to wide nodes (collapse_plan.hpp) against brute force: over small random
// trees every choice of which interior nodes stay (the root always does) is tried, and the plan must find
// the least summed area of the nodes that stay among the choices whose nodes have at most `width`
// children, and hand out members that realise it.
#include "snell/geometry/collapse_plan.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "snell/math/pcg32.hpp"

namespace {

using snell::geometry::CollapsePlan;

/// A random binary tree of `leaves` leaves, children after their parent; a parent's area is more than
/// its larger child's, as a box's is.
struct RandomTree {
  std::vector<CollapsePlan::Binary> nodes;
  snell::math::Pcg32 rng;

  RandomTree(int leaves, uint64_t seed) : rng(seed) {
    nodes.emplace_back();
    grow(0, leaves);
  }

  double grow(size_t index, int leaves) {
    if (leaves == 1) {
      nodes[index] = {1 + 9 * rng.next_double(), true, 0};
      return nodes[index].area;
    }
    const auto first = static_cast<uint32_t>(nodes.size());
    nodes.emplace_back();
    nodes.emplace_back();
    const int left = 1 + static_cast<int>(rng.next_uint() % static_cast<uint32_t>(leaves - 1));
    const double a = grow(first, left), b = grow(first + 1, leaves - left);
    nodes[index] = {std::max(a, b) * (1 + rng.next_double()), false, first};
    return nodes[index].area;
  }
};

/// The children a node that stays gets when the interior nodes marked in `kept` stay: the nearest nodes
/// below it that are leaves or stay.
int child_count(const std::vector<CollapsePlan::Binary>& t, const std::vector<bool>& kept, uint32_t b) {
  int count = 0;
  for (uint32_t c : {t[b].first_child, t[b].first_child + 1})
    count += t[c].leaf || kept[c] ? 1 : child_count(t, kept, c);
  return count;
}

/// The least summed area over the valid choices, by trying them all.
double brute_force(const std::vector<CollapsePlan::Binary>& t, int width) {
  std::vector<uint32_t> interior;
  for (uint32_t i = 1; i < t.size(); ++i)
    if (!t[i].leaf) interior.push_back(i);
  double best = INFINITY;
  for (uint32_t mask = 0; mask < (1u << interior.size()); ++mask) {
    std::vector<bool> kept(t.size(), false);
    kept[0] = true;
    for (size_t j = 0; j < interior.size(); ++j) kept[interior[j]] = (mask >> j & 1u) != 0;
    double cost = 0;
    bool valid = true;
    for (uint32_t i = 0; i < t.size() && valid; ++i)
      if (kept[i]) {
        valid = child_count(t, kept, i) <= width;
        cost += t[i].area;
      }
    if (valid) best = std::min(best, cost);
  }
  return best;
}

/// Walks the plan's members from node b: checks each node's count, that the members lie below b in the
/// tree and cover its leaves once; returns the summed area of the nodes that stay.
double realised(const std::vector<CollapsePlan::Binary>& t, const CollapsePlan& plan, uint32_t b, int width,
                std::vector<int>& leaf_seen) {
  std::array<uint32_t, CollapsePlan::kMaxWidth> members{};
  const int n = plan.members(b, members);
  EXPECT_GE(n, 2);
  EXPECT_LE(n, width);
  double cost = t[b].area;
  for (int k = 0; k < n; ++k) {
    EXPECT_GT(members[k], b) << "a member lies below its node";
    if (t[members[k]].leaf)
      ++leaf_seen[members[k]];
    else
      cost += realised(t, plan, members[k], width, leaf_seen);
  }
  return cost;
}

TEST(CollapsePlanTest, FindsTheLeastAreaCollapseOfRandomTrees) {
  int trees = 0;
  for (int width : {2, 3, 4, 8})
    for (int leaves = 2; leaves <= 13; ++leaves)
      for (uint64_t seed = 1; seed <= 6; ++seed) {
        const RandomTree tree(leaves, 1000 * static_cast<uint64_t>(leaves) + seed);
        const CollapsePlan plan(tree.nodes, width);
        const double best = brute_force(tree.nodes, width);
        ASSERT_NEAR(plan.cost(0), best, 1e-5 * best) << "width " << width << ", " << leaves << " leaves";
        std::vector<int> seen(tree.nodes.size(), 0);
        EXPECT_NEAR(realised(tree.nodes, plan, 0, width, seen), best, 1e-5 * best);
        for (size_t i = 0; i < tree.nodes.size(); ++i) {
          if (tree.nodes[i].leaf) {
            EXPECT_EQ(seen[i], 1) << "leaf " << i;
          }
        }
        ++trees;
      }
  EXPECT_EQ(trees, 4 * 12 * 6);
}

TEST(CollapsePlanTest, BinaryWidthKeepsEveryNode) {
  const RandomTree tree(40, 3);
  const CollapsePlan plan(tree.nodes, 2);
  double all = 0;
  for (const CollapsePlan::Binary& b : tree.nodes)
    if (!b.leaf) all += b.area;
  EXPECT_NEAR(plan.cost(0), all, 1e-5 * all);
}

TEST(CollapsePlanTest, AreasThatDoNotCompareStillGiveValidMembers) {
  // Boxes of NaN or infinite area (degenerate input) must not leave a node without a way to share its
  // slots: every node still gets 2 .. width members that cover its leaves once.
  for (double bad : {std::nan(""), static_cast<double>(INFINITY)}) {
    RandomTree tree(30, 11);
    for (size_t i = 0; i < tree.nodes.size(); i += 2) tree.nodes[i].area = bad;
    const CollapsePlan plan(tree.nodes, 8);
    std::vector<int> seen(tree.nodes.size(), 0);
    realised(tree.nodes, plan, 0, 8, seen);
    for (size_t i = 0; i < tree.nodes.size(); ++i) {
      if (tree.nodes[i].leaf) {
        EXPECT_EQ(seen[i], 1) << "leaf " << i;
      }
    }
  }
}

}  // namespace
