// SPDX-License-Identifier: MIT
// The contact cache (runtime/contact_cache.h) answers as a walk of both trees does, bit
// for bit, while it walks only when an object moved past its margin.
#include "runtime/contact_cache.h"

#include <gtest/gtest.h>

#include <random>

#include <glm/gtc/quaternion.hpp>

#include "scenes/random_trees.h"
#include "spheretree/tree_builder.h"

namespace frusta {
namespace {

TEST(ContactCache, AnswersAsAWalkDoesAndWalksOnlyPastItsMargin) {
  std::mt19937_64 rng(31);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int64_t touching = 0;
  for (int trial = 0; trial < 20; ++trial) {
    SphereTree trees[2];
    for (SphereTree& tree : trees)
      ASSERT_EQ(build_sphere_tree(testing::random_leaves(rng, 50 + static_cast<int>(rng() % 500), 0),
                                  {2 + static_cast<int32_t>(rng() % 15)}, &tree),
                FRUSTA_OK);
    ObjectDef a, b;
    a.pose.rotation = glm::mat3_cast(glm::normalize(glm::dquat(g(rng), g(rng), g(rng), g(rng))));
    a.linear_velocity = vec3(g(rng), g(rng), g(rng));
    b.angular_velocity = vec3(g(rng), g(rng), g(rng));
    b.pose.position = vec3(0.15, 0.0, 0.0);
    ContactCache cache;
    PatchStick stick;  // the walk's, as the cache keeps its own
    for (int step = 0; step < 300; ++step) {
      // b drifts past a by up to a millimetre a step, turning a little, and now and then
      // jumps by a centimetre; a is removed and added again (a new generation) once
      const double jump = u(rng) < 0.05 ? 0.01 : 0.001;
      b.pose.position += jump * vec3(g(rng), g(rng), g(rng)) - vec3(0.001, 0.0, 0.0);
      b.pose.rotation = glm::mat3_cast(glm::normalize(glm::quat_cast(b.pose.rotation) *
                                                      glm::dquat(1.0, 0.002 * g(rng), 0.002 * g(rng), 0.0)));
      const uint32_t generation = step < 150 ? 1 : 2;
      if (step == 150) stick = PatchStick{};  // a new object: a new pair
      const ContactSide sa{&trees[0], &a, 0.3}, sb{&trees[1], &b, 0.0};
      ObjectWrench cached_a, cached_b, walked_a, walked_b;
      const bool cached = cache.touch(3, generation, sa, 7, 1, sb, 1e-3, &cached_a, &cached_b);
      const bool walked = add_object_contact(sa, sb, 1e-3, &stick, &walked_a, &walked_b);
      cache.end_step();
      ASSERT_EQ(cached, walked) << "trial " << trial << ", step " << step;
      ASSERT_EQ(cached_a.force, walked_a.force) << "trial " << trial << ", step " << step;
      ASSERT_EQ(cached_a.torque, walked_a.torque);
      ASSERT_EQ(cached_b.force, walked_b.force);
      ASSERT_EQ(cached_b.torque, walked_b.torque);
      touching += cached ? 1 : 0;
    }
  }
  EXPECT_GT(touching, 1000) << "the trials are meant to touch";
}

// Two objects of one random tree, b 10 cm from a, which touch(): as slots sa, sb.
struct TwoObjects {
  SphereTree tree;
  ObjectDef a, b;
  TwoObjects(uint64_t seed, int leaves) {
    std::mt19937_64 rng(seed);
    EXPECT_EQ(build_sphere_tree(testing::random_leaves(rng, leaves, 0), {4}, &tree), FRUSTA_OK);
    b.pose.position = vec3(0.1, 0.0, 0.0);
  }
  bool touch(ContactCache& cache, int32_t sa, int32_t sb, ObjectWrench* on_a = nullptr,
             ObjectWrench* on_b = nullptr) const {
    ObjectWrench scratch_a, scratch_b;
    return cache.touch(sa, 1, {&tree, &a, 1.0}, sb, 1, {&tree, &b, 0.0}, 1e-3,
                       on_a ? on_a : &scratch_a, on_b ? on_b : &scratch_b);
  }
};

// What a touch() answered.
struct Answer {
  bool touching = false;
  ObjectWrench on_a, on_b;
};

// `again` is `first`, bit for bit, answered from the one walk `first` made.
void expect_answered_from_the_first_walk(const ContactCache& cache, const Answer& first,
                                         const Answer& again) {
  EXPECT_TRUE(first.touching);
  EXPECT_EQ(again.touching, first.touching);
  EXPECT_EQ(again.on_a.force, first.on_a.force);
  EXPECT_EQ(again.on_b.torque, first.on_b.torque);
  EXPECT_EQ(cache.walks(), 1);
  EXPECT_EQ(cache.reuses(), 1);
}

TEST(ContactCache, AnObjectAtRestIsNotWalkedAgain) {
  const TwoObjects objects(5, 400);
  ContactCache cache;
  for (int step = 0; step < 100; ++step) {
    objects.touch(cache, 0, 1);
    cache.end_step();
  }
  EXPECT_EQ(cache.walks(), 1);
  EXPECT_EQ(cache.reuses(), 99);
}

// A pair of objects asleep is met by no touch(); when one wakes, unmoved, its pair is
// answered from what was kept (forgotten at the step's end, it was walked again: a box
// resting on a box spent ~0.7 ms on that walk each time)
TEST(ContactCache, APairMetAgainAfterStepsWithoutItIsNotWalkedAgain) {
  const TwoObjects objects(8, 400);
  ContactCache cache;
  Answer first, again;
  first.touching = objects.touch(cache, 0, 1, &first.on_a, &first.on_b);
  for (int step = 0; step < 500; ++step) cache.end_step();
  again.touching = objects.touch(cache, 0, 1, &again.on_a, &again.on_b);
  expect_answered_from_the_first_walk(cache, first, again);
}

// A pair is met from the side of whichever object is awake: from either it is one pair,
// answered from one walk with one stick (met from the other side it was walked again,
// and its static friction started afresh: a stack kicked itself awake)
TEST(ContactCache, APairMetFromEitherSideIsOnePair) {
  const TwoObjects objects(8, 400);
  ContactCache cache;
  Answer first, again;
  first.touching = objects.touch(cache, 0, 1, &first.on_a, &first.on_b);
  cache.end_step();
  again.touching = cache.touch(1, 1, {&objects.tree, &objects.b, 0.0}, 0, 1,
                               {&objects.tree, &objects.a, 1.0}, 1e-3, &again.on_b, &again.on_a);
  expect_answered_from_the_first_walk(cache, first, again);
}

// With more pairs than it has room for, a pair that has none takes the room of the one
// met longest ago (not one met this step): the pairs met since stay answered from it.
TEST(ContactCache, APairWithoutRoomTakesThatOfThePairMetLongestAgo) {
  const TwoObjects objects(9, 200);
  ContactCache cache;
  auto touch = [&](int32_t pair) { objects.touch(cache, 2 * pair, 2 * pair + 1); };
  constexpr int32_t kPairs = ContactCache::kCachedPairs;
  for (int32_t pair = 0; pair < kPairs; ++pair) {  // one pair a step: pair 0 met first
    touch(pair);
    cache.end_step();
  }
  touch(kPairs);  // a pair more: pair 0 gives up its room
  EXPECT_EQ(cache.walks(), kPairs + 1);
  touch(kPairs);  // met again in the same step: kept
  for (int32_t pair = 1; pair < kPairs; ++pair) touch(pair);
  EXPECT_EQ(cache.walks(), kPairs + 1);
  EXPECT_EQ(cache.reuses(), kPairs);
  touch(0);  // every room met this step: walked, and kept nowhere
  touch(0);
  EXPECT_EQ(cache.walks(), kPairs + 3);
  cache.end_step();
  touch(0);  // the next step: it takes the room met longest ago
  touch(0);
  EXPECT_EQ(cache.walks(), kPairs + 4);
}

}  // namespace
}  // namespace frusta
