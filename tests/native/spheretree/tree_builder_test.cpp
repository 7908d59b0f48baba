// SPDX-License-Identifier: MIT
#include "spheretree/tree_builder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "scenes/random_trees.h"

namespace frusta {
namespace {

// every leaf lies inside every ancestor's bound, every leaf is reached once
void expect_valid(const SphereTree& tree, const std::vector<Sphere>& leaves) {
  std::vector<int> seen(leaves.size(), 0);
  struct Entry {
    int32_t node, level;
    std::vector<int32_t> ancestors;
  };
  std::vector<Entry> stack{{0, 0, {}}};
  while (!stack.empty()) {
    Entry e = stack.back();
    stack.pop_back();
    const TreeNode& n = tree.nodes[static_cast<size_t>(e.node)];
    ASSERT_LE(e.level, tree.depth);
    e.ancestors.push_back(e.node);
    if (n.count == 0) {
      ++seen[static_cast<size_t>(n.first)];
      const Sphere& leaf = leaves[static_cast<size_t>(n.first)];
      for (int32_t a : e.ancestors) {
        const Sphere b = tree.node_sphere(a);
        EXPECT_LE(glm::length(leaf.center - b.center) + leaf.radius, static_cast<double>(b.radius))
            << "leaf " << n.first << " outside node " << a;
      }
      continue;
    }
    ASSERT_GE(n.count, 2);  // no chains of single children
    ASSERT_LE(n.count, tree.branching);
    ASSERT_GT(n.first, e.node);
    for (int32_t c = 0; c < n.count; ++c) stack.push_back({n.first + c, e.level + 1, e.ancestors});
  }
  for (size_t i = 0; i < leaves.size(); ++i) EXPECT_EQ(seen[i], 1) << "leaf " << i;
}

TEST(TreeBuilder, EveryLeafOnceAndInsideAllItsAncestors) {
  std::mt19937_64 rng(17);
  for (int trial = 0; trial < 40; ++trial) {
    const int count = 1 + static_cast<int>(rng() % 4000);
    const std::vector<Sphere> leaves = testing::random_leaves(rng, count, trial % 4);
    SphereTree tree;
    const int32_t branching = 2 + trial % 15;
    ASSERT_EQ(build_sphere_tree(leaves, {branching}, &tree), FRUSTA_OK);
    EXPECT_EQ(tree.leaves.size(), leaves.size());
    for (size_t i = 0; i < leaves.size(); ++i) {  // numbering is the caller's
      EXPECT_EQ(tree.leaves[i].center, leaves[i].center);
      EXPECT_EQ(tree.leaves[i].radius, leaves[i].radius);
    }
    expect_valid(tree, leaves);
    // balanced: depth is ceil(log_b n) plus at most one level where the leaf count does not divide evenly
    const double ideal = count > 1 ? std::ceil(std::log(count) / std::log(branching)) : 0.0;
    EXPECT_LE(tree.depth, ideal + 1) << count << " leaves, branching " << branching;
  }
}

TEST(TreeBuilder, RefusesBadInputWithAMessage) {
  SphereTree tree;
  EXPECT_EQ(build_sphere_tree({}, {4}, &tree), FRUSTA_ERROR_OUT_OF_RANGE);
  const std::vector<Sphere> one{{vec3(0.0), 0.01}};
  EXPECT_EQ(build_sphere_tree(one, {1}, &tree), FRUSTA_ERROR_OUT_OF_RANGE);
  EXPECT_EQ(build_sphere_tree(one, {17}, &tree), FRUSTA_ERROR_OUT_OF_RANGE);
  const std::vector<Sphere> nan{{vec3(0.0), 0.01}, {vec3(std::nan(""), 0, 0), 0.01}};
  EXPECT_EQ(build_sphere_tree(nan, {4}, &tree), FRUSTA_ERROR_NOT_FINITE);
  EXPECT_NE(std::string(frusta::last_error_message()).find("leaf 1"), std::string::npos);
  const std::vector<Sphere> negative{{vec3(0.0), -0.01}};
  EXPECT_EQ(build_sphere_tree(negative, {4}, &tree), FRUSTA_ERROR_OUT_OF_RANGE);
}

TEST(TreeBuilder, BoundsAreTightForASingleLeaf) {
  SphereTree tree;
  ASSERT_EQ(build_sphere_tree({{vec3(0.01, 0.02, 0.03), 0.005}}, {4}, &tree), FRUSTA_OK);
  ASSERT_EQ(tree.nodes.size(), 1u);
  EXPECT_EQ(tree.depth, 0);
  EXPECT_NEAR(tree.nodes[0].radius, 0.005, 1e-8);  // a few float ulps, never less
  EXPECT_GE(static_cast<double>(tree.nodes[0].radius) +
                1e-7 /* float centre rounding */, 0.005);
}

}  // namespace
}  // namespace frusta
