// SPDX-License-Identifier: MIT
#include "spheretree/node_error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include <glm/geometric.hpp>

#include "scenes/random_trees.h"
#include "spheretree/tree_builder.h"

namespace frusta {
namespace {

// the leaves below a node, by brute force
void leaves_below(const SphereTree& tree, int32_t node, std::vector<Sphere>& out) {
  const TreeNode& n = tree.nodes[static_cast<size_t>(node)];
  if (n.count == 0) {
    out.push_back(tree.leaves[static_cast<size_t>(n.first)]);
    return;
  }
  for (int32_t c = 0; c < n.count; ++c) leaves_below(tree, n.first + c, out);
}

double gap_to(const std::vector<Sphere>& leaves, const vec3& p) {
  double nearest = INFINITY;
  for (const Sphere& s : leaves) nearest = std::min(nearest, glm::length(p - s.center) - s.radius);
  return std::max(0.0, nearest);
}

vec3 random_direction(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  return glm::normalize(vec3(g(rng), g(rng), g(rng)));
}

// The largest angle from any direction to its nearest lattice direction, sampled densely:
// how far between its samples a node's surface may stand out more (times the radius).
double lattice_gap(std::mt19937_64& rng) {
  double gap = 0.0;
  for (int i = 0; i < 200000; ++i) {
    const vec3 d = random_direction(rng);
    double best = -1.0;
    for (const vec3& l : node_error_directions()) best = std::max(best, glm::dot(d, l));
    gap = std::max(gap, std::acos(std::min(1.0, best)));
  }
  return gap;
}

class NodeErrorTest : public ::testing::TestWithParam<int> {};

// At every sampled point of every node's surface, the node's error is no less than the
// exact gap from there to its leaves (the children's bounds over-estimate, never under);
// anywhere on the surface, no less than that gap minus the lattice's gap times the radius.
TEST_P(NodeErrorTest, BoundsTheGapFromANodesSurfaceToItsLeaves) {
  std::mt19937_64 rng(static_cast<uint64_t>(GetParam()) + 11);
  const double lattice = lattice_gap(rng);
  EXPECT_LT(lattice, 0.35);  // a guard that the lattice stays nearly even (0.34 rad)
  const int kind = GetParam();
  const std::vector<Sphere> leaves =
      kind < 4 ? testing::random_leaves(rng, 600, kind) : testing::plate_leaves(rng, 30, 30, 0.001, 0.0006);
  SphereTree tree;
  ASSERT_EQ(build_sphere_tree(leaves, {kind % 2 == 0 ? 4 : 8}, &tree), FRUSTA_OK);
  ASSERT_EQ(tree.node_error.size(), tree.nodes.size());
  int inner = 0;
  for (size_t i = 0; i < tree.nodes.size(); ++i) {
    const TreeNode& n = tree.nodes[i];
    if (n.count == 0) {
      EXPECT_EQ(tree.node_error[i], 0.0f);
      continue;
    }
    ++inner;
    std::vector<Sphere> below;
    leaves_below(tree, static_cast<int32_t>(i), below);
    const Sphere bound = tree.node_sphere(static_cast<int32_t>(i));
    const double error = tree.node_error[i];
    for (const vec3& d : node_error_directions())
      EXPECT_LE(gap_to(below, bound.center + bound.radius * d), error) << "node " << i;
    for (int k = 0; k < 64; ++k)
      EXPECT_LE(gap_to(below, bound.center + bound.radius * random_direction(rng)),
                error + bound.radius * lattice)
          << "node " << i;
  }
  EXPECT_GT(inner, 10);
}

INSTANTIATE_TEST_SUITE_P(LeafSets, NodeErrorTest, ::testing::Values(0, 1, 2, 3, 4));

// A cut by error stands an inner node in for its leaves only where its error is within.
TEST(NodeError, ACutByErrorStopsOnlyAtNodesWithinIt) {
  std::mt19937_64 rng(5);
  SphereTree tree;
  ASSERT_EQ(build_sphere_tree(testing::plate_leaves(rng, 40, 40, 0.001, 0.0006), {4}, &tree), FRUSTA_OK);
  for (double budget : {0.0005, 0.001, 0.003}) {
    int32_t inner_hits = 0;
    walk_tree(tree, [](const Sphere&) { return true; }, TreeCut(-1, budget), [&](const TreeHit& h) {
      if (h.leaf >= 0) return;
      ++inner_hits;
      EXPECT_LE(tree.node_error[static_cast<size_t>(h.node)], budget);
    });
    EXPECT_GT(inner_hits, 0) << budget;
  }
}

}  // namespace
}  // namespace frusta
