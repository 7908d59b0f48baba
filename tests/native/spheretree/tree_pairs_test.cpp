// SPDX-License-Identifier: MIT
// The dual walk of two trees (spheretree/tree_pairs.h) finds exactly the overlapping
// leaf pairs a scan of every pair finds.
#include "spheretree/tree_pairs.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <iterator>
#include <random>
#include <utility>
#include <vector>

#include <glm/gtc/quaternion.hpp>

#include "scenes/random_cases.h"
#include "scenes/random_trees.h"
#include "spheretree/tree_builder.h"

namespace frusta {
namespace {

TEST(TreePairs, TheDualWalkFindsEveryOverlappingPairAScanFinds) {
  std::mt19937_64 rng(77);
  std::uniform_real_distribution<double> u(-0.1, 0.1);
  std::normal_distribution<double> g;
  long pairs = 0;
  const int trials = scenes::scaled_case_count(200, 20);
  for (int trial = 0; trial < trials; ++trial) {
    SphereTree trees[2];
    std::vector<Sphere> leaves[2];
    for (int k = 0; k < 2; ++k) {
      leaves[k] = testing::random_leaves(rng, 1 + static_cast<int>(rng() % 600), (trial + k) % 4);
      ASSERT_EQ(build_sphere_tree(leaves[k], {2 + static_cast<int32_t>(rng() % 15)}, &trees[k]), FRUSTA_OK);
    }
    RigidPose b_in_a;
    b_in_a.position = vec3(u(rng), u(rng), u(rng));
    b_in_a.rotation = glm::mat3_cast(glm::normalize(glm::dquat(g(rng), g(rng), g(rng), g(rng))));
    std::vector<std::pair<int32_t, int32_t>> found, scanned;
    walk_overlapping_leaves(trees[0], trees[1], b_in_a,
                            [&](int32_t a, int32_t b, const Sphere& sa, const Sphere& sb) {
                              EXPECT_EQ(sa.radius, leaves[0][static_cast<size_t>(a)].radius);
                              EXPECT_EQ(sb.radius, leaves[1][static_cast<size_t>(b)].radius);
                              found.emplace_back(a, b);
                            });
    for (size_t a = 0; a < leaves[0].size(); ++a)
      for (size_t b = 0; b < leaves[1].size(); ++b) {
        const vec3 cb = b_in_a.position + b_in_a.rotation * leaves[1][b].center;
        const double reach = leaves[0][a].radius + leaves[1][b].radius;
        const vec3 d = leaves[0][a].center - cb;
        if (glm::dot(d, d) < reach * reach)
          scanned.emplace_back(static_cast<int32_t>(a), static_cast<int32_t>(b));
      }
    std::sort(found.begin(), found.end());
    ASSERT_TRUE(std::adjacent_find(found.begin(), found.end()) == found.end()) << "a pair twice";
    EXPECT_EQ(found, scanned) << "trial " << trial;
    pairs += static_cast<long>(scanned.size());
  }
  EXPECT_GT(pairs, 5L * trials) << "the trials are meant to overlap";
}

TEST(TreePairs, AnEmptyTreeMeetsNothing) {
  SphereTree empty, one;
  ASSERT_EQ(build_sphere_tree({Sphere{vec3(0.0), 1.0}}, {4}, &one), FRUSTA_OK);
  int calls = 0;
  auto count = [&](int32_t, int32_t, const Sphere&, const Sphere&) { ++calls; };
  EXPECT_EQ(walk_overlapping_leaves(empty, one, RigidPose{}, count), 0);
  EXPECT_EQ(walk_overlapping_leaves(one, empty, RigidPose{}, count), 0);
  EXPECT_EQ(walk_overlapping_leaves(one, one, RigidPose{}, count), 1);
  EXPECT_EQ(calls, 1);
}

}  // namespace
}  // namespace frusta
