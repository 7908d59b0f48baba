// SPDX-License-Identifier: MIT
#include "spheretree/sphere_tree.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <glm/gtc/quaternion.hpp>

#include "geometry/contact_test.h"
#include "geometry/exact_distance.h"
#include "scenes/random_cases.h"
#include "scenes/random_trees.h"
#include "spheretree/tree_builder.h"

namespace frusta {
namespace {

std::vector<int32_t> sorted_leaves(const TreeHit* hits, int32_t count) {
  std::vector<int32_t> out;
  for (int32_t i = 0; i < count; ++i) out.push_back(hits[i].leaf);
  std::sort(out.begin(), out.end());
  return out;
}

// Property: a query returns exactly the leaves a brute-force scan of every leaf
// returns, for random trees (sizes, shapes, branching), segments, poses and margins.
TEST(SphereTree, SegmentQueryEqualsBruteForceScan) {
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> u(-0.15, 0.15), r(0.0, 0.015), margin(0.0, 0.01);
  std::normal_distribution<double> g;
  std::vector<TreeHit> hits(20000);
  long compared = 0, nonempty = 0;
  const int trials = scenes::scaled_case_count(300, 30);
  for (int trial = 0; trial < trials; ++trial) {
    const int count = 1 + static_cast<int>(rng() % 3000);
    const std::vector<Sphere> leaves = testing::random_leaves(rng, count, trial % 4);
    SphereTree tree;
    ASSERT_EQ(build_sphere_tree(leaves, {2 + static_cast<int32_t>(rng() % 15)}, &tree), FRUSTA_OK);
    RigidPose pose;
    pose.position = vec3(u(rng), u(rng), u(rng)) * 10.0;
    pose.rotation = glm::mat3_cast(glm::normalize(glm::dquat(g(rng), g(rng), g(rng), g(rng))));
    for (int q = 0; q < 20; ++q) {
      // a world segment near the object's world placement
      const vec3 a = pose.position + pose.rotation * vec3(u(rng), u(rng), u(rng));
      const vec3 b = a + 0.05 * vec3(g(rng), g(rng), g(rng));
      const Segment world{a, b, r(rng), r(rng)};
      const double m = margin(rng);
      const SegmentFrame frame = make_segment_frame(to_object_frame(pose, world));
      const TreeQueryStats stats = query_segment(tree, frame, m, -1, hits.data(), 20000);
      ASSERT_LE(stats.hits, 20000);
      std::vector<int32_t> brute;
      // brute force in the world frame: the pose transform must not change the answer
      const SegmentFrame world_frame = make_segment_frame(world);
      for (int32_t i = 0; i < count; ++i) {
        const Sphere w{pose.position + pose.rotation * leaves[static_cast<size_t>(i)].center,
                       leaves[static_cast<size_t>(i)].radius};
        if (may_touch(world_frame, w, m)) brute.push_back(i);
      }
      const std::vector<int32_t> found = sorted_leaves(hits.data(), stats.hits);
      // transforming rounds differently by ~1e-17 m: allow only leaves exactly at the boundary
      std::vector<int32_t> diff;
      std::set_symmetric_difference(found.begin(), found.end(), brute.begin(), brute.end(),
                                    std::back_inserter(diff));
      for (int32_t leaf : diff) {
        const Sphere& s = leaves[static_cast<size_t>(leaf)];
        const Sphere grown{s.center, s.radius + 1e-12}, shrunk{s.center, std::max(0.0, s.radius - 1e-12)};
        EXPECT_TRUE(may_touch(frame, grown, m) && !may_touch(frame, shrunk, m))
            << "leaf " << leaf << " differs and is not on the boundary";
      }
      compared += count;
      nonempty += !brute.empty();
    }
  }
  EXPECT_GT(nonempty, trials * 20 / 6);  // the segments do hit things
  EXPECT_GT(compared, 3000L * trials);
}

// query_segment culls a node's children in single precision and tests exactly each node
// it may report: it must find what walk_tree testing every node with may_touch finds, hit
// for hit and in the same order (query_segment_loose, which stops at the culling, at
// least that), on random trees (far from the origin too, where single precision is
// coarse), margins and cuts (to the leaves, at a level, by an error budget), with
// segments that graze a leaf at the margin.
TEST(SphereTree, SegmentQueryMatchesTheExactWalkHitForHit) {
  std::mt19937_64 rng(77);
  std::uniform_real_distribution<double> u(-0.12, 0.12), r(0.0, 0.015), margin(0.0, 0.01);
  std::normal_distribution<double> g;
  std::vector<TreeHit> hits(20000), loose(20000);
  long compared = 0, grazing = 0, cut_hits = 0, loose_extra = 0;
  const int trials = scenes::scaled_case_count(200, 20);
  for (int trial = 0; trial < trials; ++trial) {
    std::vector<Sphere> leaves =
        testing::random_leaves(rng, 1 + static_cast<int>(rng() % 3000), trial % 4);
    const vec3 offset = trial % 3 == 0 ? vec3(u(rng), u(rng), u(rng)) * 1000.0 : vec3(0.0);
    for (Sphere& s : leaves) s.center += offset;
    SphereTree tree;
    ASSERT_EQ(build_sphere_tree(leaves, {2 + static_cast<int32_t>(rng() % 15)}, &tree), FRUSTA_OK);
    for (int q = 0; q < 20; ++q) {
      const vec3 a = offset + vec3(u(rng), u(rng), u(rng));
      const Segment segment{a, a + 0.05 * vec3(g(rng), g(rng), g(rng)), r(rng), r(rng)};
      const SegmentFrame frame = make_segment_frame(segment);
      double m = margin(rng);
      if (q % 2 == 1) {  // the margin at which some leaf just touches
        m = std::max(0.0, exact_distance(frame, leaves[rng() % leaves.size()]));
        ++grazing;
      }
      const TreeCut cut = q % 3 == 0   ? TreeCut()
                          : q % 3 == 1 ? TreeCut(static_cast<int32_t>(rng() % 4))
                                       : TreeCut(-1, 0.02 * margin(rng));
      const TreeQueryStats stats = query_segment(tree, frame, m, cut, hits.data(), 20000);
      std::vector<TreeHit> exact;
      walk_tree(tree, [&](const Sphere& s) { return may_touch(frame, s, m); }, cut,
                [&](const TreeHit& h) { exact.push_back(h); });
      cut_hits += cut.cuts() ? static_cast<long>(std::count_if(exact.begin(), exact.end(),
                                                               [](const TreeHit& h) { return h.leaf < 0; }))
                             : 0;
      ASSERT_EQ(stats.hits, static_cast<int32_t>(exact.size())) << "trial " << trial << " query " << q;
      for (size_t i = 0; i < exact.size(); ++i) {
        ASSERT_EQ(hits[i].node, exact[i].node) << "trial " << trial << " query " << q << " hit " << i;
        ASSERT_EQ(hits[i].leaf, exact[i].leaf);
      }
      compared += stats.hits;
      // the loose query: every exact hit in the same order, and the others within its
      // single-precision slack of the margin (a node the cut stops at, within its overhang)
      const TreeQueryStats loose_stats =
          query_segment_loose(tree, frame, m, cut, loose.data(), 20000);
      ASSERT_LE(loose_stats.hits, 20000);
      size_t next = 0;
      for (int32_t i = 0; i < loose_stats.hits; ++i) {
        const TreeHit& h = loose[static_cast<size_t>(i)];
        if (next < exact.size() && h.node == exact[next].node) {
          ASSERT_EQ(h.leaf, exact[next].leaf);
          ++next;
          continue;
        }
        Sphere s = walked_sphere(tree, h.node, h.leaf < 0, cut);
        if (h.leaf < 0)
          s.radius += static_cast<double>(tree.node_overhang[static_cast<size_t>(h.node)]);
        // the sizes its rounding is relative to (1-norms, as the test's own): the sphere's
        // and the segment's, from the origin; its slack is 2^-17 of them
        auto norm1 = [](const vec3& v) { return std::fabs(v.x) + std::fabs(v.y) + std::fabs(v.z); };
        const double scale =
            norm1(s.center - frame.distal) + norm1(frame.distal) + frame.size + s.radius + m;
        EXPECT_TRUE(may_touch(frame, s, m + 2e-5 * scale))
            << "trial " << trial << " query " << q << " hit " << i;
        ++loose_extra;
      }
      ASSERT_EQ(next, exact.size())
          << "trial " << trial << " query " << q << ": an exact hit is missing";
    }
  }
  EXPECT_GT(compared, 500L * trials);
  EXPECT_GT(grazing, 5L * trials);
  EXPECT_GT(cut_hits, 50L * trials);  // inner nodes reported where a cut stopped
  EXPECT_LT(loose_extra, compared / 10);  // the loose query keeps few more
}

TEST(SphereTree, SphereQueryEqualsBruteForceScan) {
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> u(-0.12, 0.12), r(0.0, 0.02);
  std::vector<TreeHit> hits(5000);
  const int trials = scenes::scaled_case_count(200, 20);
  for (int trial = 0; trial < trials; ++trial) {
    const std::vector<Sphere> leaves = testing::random_leaves(rng, 2000, trial % 4);
    SphereTree tree;
    ASSERT_EQ(build_sphere_tree(leaves, {4}, &tree), FRUSTA_OK);
    const Sphere probe{vec3(u(rng), u(rng), u(rng)), r(rng)};
    const TreeQueryStats stats = query_sphere(tree, probe, 0.001, -1, hits.data(), 5000);
    std::vector<int32_t> brute;
    for (int32_t i = 0; i < 2000; ++i)
      if (may_touch_sphere(probe, leaves[static_cast<size_t>(i)], 0.001)) brute.push_back(i);
    EXPECT_EQ(sorted_leaves(hits.data(), stats.hits), brute);
  }
}

TEST(SphereTree, CullingVisitsFewNodesWhenLittleIsNear) {
  std::mt19937_64 rng(5);
  const std::vector<Sphere> leaves = testing::random_leaves(rng, 100000, 1);  // a shell
  SphereTree tree;
  ASSERT_EQ(build_sphere_tree(leaves, {8}, &tree), FRUSTA_OK);
  TreeHit hits[256];
  // a fingertip-sized segment touching the shell at one spot
  const SegmentFrame frame =
      make_segment_frame({vec3(0.0, 0.0, 0.11), vec3(0.0, 0.0, 0.085), 0.01, 0.008});
  const TreeQueryStats near = query_segment(tree, frame, 0.002, -1, hits, 256);
  EXPECT_GT(near.hits, 0);
  EXPECT_LT(near.visited, 2000);  // of ~114k nodes
  // far away: the root alone is tested
  const SegmentFrame far = make_segment_frame({vec3(1, 1, 1), vec3(1.05, 1, 1), 0.01, 0.008});
  EXPECT_EQ(query_segment(tree, far, 0.002, -1, hits, 256).visited, 1);
}

TEST(SphereTree, LevelCutReportsInnerNodesThatBoundTheirLeaves) {
  std::mt19937_64 rng(8);
  const std::vector<Sphere> leaves = testing::random_leaves(rng, 5000, 0);
  SphereTree tree;
  ASSERT_EQ(build_sphere_tree(leaves, {4}, &tree), FRUSTA_OK);
  std::vector<TreeHit> all(5000), cut(5000);
  const SegmentFrame frame = make_segment_frame({vec3(-0.1, 0, 0), vec3(0.1, 0, 0), 0.01, 0.01});
  const int32_t leaves_hit = query_segment(tree, frame, 0.0, -1, all.data(), 5000).hits;
  const int32_t nodes_hit = query_segment(tree, frame, 0.0, 2, cut.data(), 5000).hits;
  EXPECT_GT(leaves_hit, nodes_hit);
  EXPECT_LE(nodes_hit, 16);  // level 2 of a 4-ary tree has at most 16 nodes
  for (int32_t i = 0; i < nodes_hit; ++i) EXPECT_EQ(cut[static_cast<size_t>(i)].leaf, -1);
}

// Both segment queries, into buffers of every size up to the whole answer: the first hits
// of the whole answer, in its order, nothing written past the buffer, and every hit counted
// (the loose walk reports a node's leaf children at once only where all of them fit).
TEST(SphereTree, HitsBeyondCapacityAreCountedNotWritten) {
  std::mt19937_64 rng(3);
  const std::vector<Sphere> leaves = testing::random_leaves(rng, 1000, 0);
  SphereTree tree;
  ASSERT_EQ(build_sphere_tree(leaves, {4}, &tree), FRUSTA_OK);
  const SegmentFrame frame = make_segment_frame({vec3(-0.2, 0, 0), vec3(0.2, 0, 0), 0.05, 0.05});
  for (const bool loose : {false, true}) {
    auto query = [&](TreeHit* hits, int32_t capacity) {
      return loose ? query_segment_loose(tree, frame, 0.0, -1, hits, capacity)
                   : query_segment(tree, frame, 0.0, -1, hits, capacity);
    };
    std::vector<TreeHit> whole(2000);
    const int32_t all = query(whole.data(), 2000).hits;
    ASSERT_GT(all, 20);
    ASSERT_LT(all, 2000);
    for (int32_t capacity = 0; capacity <= all; ++capacity) {
      std::vector<TreeHit> hits(static_cast<size_t>(capacity) + 1, TreeHit{-7, -7});
      EXPECT_EQ(query(hits.data(), capacity).hits, all) << loose << " " << capacity;
      for (int32_t i = 0; i < capacity; ++i) {
        ASSERT_EQ(hits[static_cast<size_t>(i)].node, whole[static_cast<size_t>(i)].node)
            << loose << " " << capacity;
        ASSERT_EQ(hits[static_cast<size_t>(i)].leaf, whole[static_cast<size_t>(i)].leaf);
      }
      EXPECT_EQ(hits[static_cast<size_t>(capacity)].node, -7)
          << loose << " " << capacity;  // untouched
    }
  }
}

}  // namespace
}  // namespace frusta
