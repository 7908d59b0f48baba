// SPDX-License-Identifier: MIT
// The broad phase's tree against a brute-force scan of the same boxes, through random
// inserts, removals, small and large moves, with its structure checked after each.
#include "solver/broad_phase.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

namespace frusta {
namespace {

Aabb random_box(std::mt19937_64& rng, double room, double size) {
  std::uniform_real_distribution<double> at(-room, room), extent(0.001, size);
  const vec3 c(at(rng), at(rng), at(rng));
  const vec3 h(extent(rng), extent(rng), extent(rng));
  return {c - h, c + h};
}

Aabb fat(const Aabb& b) { return {b.lower - BroadPhase::kFatMargin, b.upper + BroadPhase::kFatMargin}; }

std::vector<int32_t> query(const BroadPhase& tree, const Aabb& box) {
  std::vector<int32_t> hits;
  tree.query(box, [&](int32_t user) { hits.push_back(user); });
  std::sort(hits.begin(), hits.end());
  return hits;
}

TEST(BroadPhase, EmptyTreeFindsNothing) {
  BroadPhase tree(4);
  EXPECT_TRUE(tree.valid());
  EXPECT_TRUE(query(tree, {vec3(-1e9), vec3(1e9)}).empty());
  EXPECT_EQ(tree.height(), 0);
}

TEST(BroadPhase, RefusesPastCapacityAndReusesFreedNodes) {
  BroadPhase tree(3);
  int32_t p[3];
  for (int i = 0; i < 3; ++i) p[i] = tree.create_proxy({vec3(i), vec3(i + 0.5)}, i);
  EXPECT_EQ(tree.create_proxy({vec3(9), vec3(10)}, 3), BroadPhase::kNull);
  EXPECT_EQ(tree.proxy_count(), 3);
  EXPECT_TRUE(tree.valid());
  tree.destroy_proxy(p[1]);
  EXPECT_TRUE(tree.valid());
  const int32_t again = tree.create_proxy({vec3(9), vec3(10)}, 7);
  ASSERT_NE(again, BroadPhase::kNull);
  EXPECT_EQ(tree.user(again), 7);
  EXPECT_EQ(query(tree, {vec3(8.9), vec3(9.1)}), std::vector<int32_t>{7});
  EXPECT_TRUE(tree.valid());
}

TEST(BroadPhase, SmallMovesStayInTheFatBox) {
  BroadPhase tree(2);
  const Aabb box{vec3(0.0), vec3(0.1)};
  const int32_t p = tree.create_proxy(box, 0);
  const vec3 nudge(0.5 * BroadPhase::kFatMargin);
  EXPECT_FALSE(tree.move_proxy(p, {box.lower + nudge, box.upper + nudge}));
  EXPECT_TRUE(tree.move_proxy(p, {box.lower + 3.0 * nudge, box.upper + 3.0 * nudge}));
  EXPECT_TRUE(contains(tree.fat_box(p), {box.lower + 3.0 * nudge, box.upper + 3.0 * nudge}));
  EXPECT_TRUE(tree.valid());
}

// Random operations on 1,000 boxes in a 10 m room; after each batch every query by a
// random box answers exactly the users whose fat boxes meet it (what the tree
// promises), and those always include every user whose true box meets it.
TEST(BroadPhase, QueriesEqualBruteForceThroughRandomChanges) {
  constexpr int32_t kCapacity = 1000;
  std::mt19937_64 rng(21);
  BroadPhase tree(kCapacity);
  std::vector<int32_t> proxy(kCapacity, BroadPhase::kNull);
  std::vector<Aabb> truth(kCapacity), fat_box(kCapacity);
  std::uniform_int_distribution<int32_t> pick(0, kCapacity - 1), op(0, 9);
  std::normal_distribution<double> small(0.0, 0.004);
  int32_t checked = 0;
  for (int batch = 0; batch < 60; ++batch) {
    for (int k = 0; k < 200; ++k) {
      const int32_t u = pick(rng);
      const int o = op(rng);
      if (proxy[u] == BroadPhase::kNull) {
        truth[u] = random_box(rng, 5.0, 0.2);
        proxy[u] = tree.create_proxy(truth[u], u);
        ASSERT_NE(proxy[u], BroadPhase::kNull);
        fat_box[u] = fat(truth[u]);
      } else if (o == 0) {
        tree.destroy_proxy(proxy[u]);
        proxy[u] = BroadPhase::kNull;
      } else {
        // mostly small moves (a held object), some jumps across the room
        Aabb moved = truth[u];
        if (o < 8) {
          const vec3 d(small(rng), small(rng), small(rng));
          moved = {moved.lower + d, moved.upper + d};
        } else {
          moved = random_box(rng, 5.0, 0.2);
        }
        const bool reinserted = tree.move_proxy(proxy[u], moved);
        EXPECT_EQ(reinserted, !contains(fat_box[u], moved));
        if (reinserted) fat_box[u] = fat(moved);
        truth[u] = moved;
      }
    }
    ASSERT_TRUE(tree.valid()) << "batch " << batch;
    for (int q = 0; q < 20; ++q) {
      const Aabb box = random_box(rng, 5.5, 1.0);
      std::vector<int32_t> want;
      for (int32_t u = 0; u < kCapacity; ++u)
        if (proxy[u] != BroadPhase::kNull && overlaps(fat_box[u], box)) want.push_back(u);
      const std::vector<int32_t> got = query(tree, box);
      ASSERT_EQ(got, want) << "batch " << batch << " query " << q;
      for (int32_t u = 0; u < kCapacity; ++u) {
        if (proxy[u] != BroadPhase::kNull && overlaps(truth[u], box)) {
          EXPECT_TRUE(std::binary_search(got.begin(), got.end(), u));
        }
      }
      checked += static_cast<int32_t>(want.size());
    }
  }
  EXPECT_GT(checked, 100);  // the queries did meet boxes
  // a balanced tree: far shallower than a list of 1000
  EXPECT_LE(tree.height(), 30);
}

TEST(BroadPhase, FillsToCapacityAndEmptiesAgain) {
  constexpr int32_t kCapacity = 257;
  std::mt19937_64 rng(7);
  BroadPhase tree(kCapacity);
  std::vector<int32_t> proxy;
  for (int32_t u = 0; u < kCapacity; ++u) proxy.push_back(tree.create_proxy(random_box(rng, 1.0, 0.05), u));
  EXPECT_EQ(tree.create_proxy(random_box(rng, 1.0, 0.05), kCapacity), BroadPhase::kNull);
  EXPECT_TRUE(tree.valid());
  EXPECT_EQ(query(tree, {vec3(-2.0), vec3(2.0)}).size(), static_cast<size_t>(kCapacity));
  for (int32_t u = 0; u < kCapacity; u += 2) tree.destroy_proxy(proxy[static_cast<size_t>(u)]);
  EXPECT_TRUE(tree.valid());
  for (int32_t u = 1; u < kCapacity; u += 2) tree.destroy_proxy(proxy[static_cast<size_t>(u)]);
  EXPECT_TRUE(tree.valid());
  EXPECT_EQ(tree.proxy_count(), 0);
  EXPECT_TRUE(query(tree, {vec3(-2.0), vec3(2.0)}).empty());
}

}  // namespace
}  // namespace frusta
