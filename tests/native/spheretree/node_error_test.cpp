// SPDX-License-Identifier: MIT
#include "spheretree/node_error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include <glm/geometric.hpp>

#include "scenes/random_trees.h"
#include "geometry/contact_test.h"
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

// Under a cut, a node that stands in is found by any walk whose margin reaches its own
// sphere, whichever way its ancestors' spheres lie: a parent bounds its leaves, not its
// children's spheres, which the walk reaches through the tree's node_overhang. A walk
// at a small margin finds exactly the hits of one at a large margin that lie within the
// small one (before, a touching hand's 0.25 mm walk found nothing the 2 mm walk did).
TEST(NodeError, ASmallMarginFindsEveryStandInALargeOneFindsWithinIt) {
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (const auto& leaves : {testing::plate_leaves(rng, 60, 60, 0.0007, 0.0006),
                             testing::random_leaves(rng, 4000, 1)}) {
    SphereTree tree;
    ASSERT_EQ(build_sphere_tree(leaves, {8}, &tree), FRUSTA_OK);
    int64_t checked = 0, missed = 0;
    for (TreeCut cut : {TreeCut(-1, 0.0005), TreeCut(-1, 0.001), TreeCut(2, 0.0)}) {
      for (int trial = 0; trial < 300; ++trial) {
        // a finger segment lying a hair off a random leaf
        const Sphere& near = leaves[static_cast<size_t>(rng() % leaves.size())];
        const vec3 on = near.center + (near.radius + 0.008 + 0.0005 * (1.0 + unit(rng))) *
                                          glm::normalize(vec3(unit(rng), unit(rng), unit(rng)));
        const vec3 along = glm::normalize(vec3(unit(rng), unit(rng), unit(rng)));
        const SegmentFrame frame = make_segment_frame({on + 0.01 * along, on - 0.01 * along, 0.008, 0.007});
        std::vector<TreeHit> big(20000), small(20000);
        const int32_t nb = query_segment(tree, frame, 0.004, cut, big.data(), 20000).hits;
        const int32_t ns = query_segment(tree, frame, 0.0005, cut, small.data(), 20000).hits;
        ASSERT_LE(nb, 20000);
        int32_t within = 0;
        for (int32_t i = 0; i < nb; ++i) {
          const TreeHit& h = big[static_cast<size_t>(i)];
          const Sphere s = h.leaf >= 0 ? tree.leaves[static_cast<size_t>(h.leaf)] : tree.node_sphere(h.node);
          if (!may_touch(frame, s, 0.0005)) continue;
          ++within;
          missed += std::none_of(small.begin(), small.begin() + ns,
                                 [&](const TreeHit& x) { return x.node == h.node; });
        }
        EXPECT_EQ(within, ns) << "trial " << trial;
        checked += within;
      }
    }
    EXPECT_EQ(missed, 0);
    EXPECT_GT(checked, 1000);
  }
}

}  // namespace
}  // namespace frusta
