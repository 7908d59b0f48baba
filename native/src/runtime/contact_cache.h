// SPDX-License-Identifier: MIT
// Object contacts without walking both trees every step (runtime/object_contact.h). A
// walk with a margin keeps the leaf pairs closer than it; while b has moved less than
// the margin against a (its farthest leaf included), every pair that overlaps now is
// among those kept, so a step tests only them, in the walk's order: the answer is the
// walk's, bit for bit. Where sphere bounds cover flat faces, walks are dear: a box
// resting on a box tested 37,800 node pairs a step for 87 overlapping leaf pairs.
//
// Sized when the world is built (512 KB): kCachedPairs object pairs of at most
// kCachedLeafPairs leaf pairs each; a pair beyond either is walked every step. A 0.2 kg
// box landing on a box at 0.6 m/s sinks 2 mm for a few steps, when the walk's margin
// keeps up to 6,100 pairs: at 4,096 those steps all walked (settling p99 790 us).
//
// Threads: the stepping thread only.
#pragma once

#include <cstdint>
#include <vector>

#include "runtime/object_contact.h"

namespace frusta {

class ContactCache {
 public:
  static constexpr int32_t kCachedPairs = 8;
  static constexpr int32_t kCachedLeafPairs = 8192;
  static constexpr double kMargin = 0.0005;  // metres

  ContactCache();

  // add_object_contact(a, b, ...)'s answer. sa, sb: the objects' slots, ga, gb their
  // generations (an object added in a slot is not the one cached for it).
  bool touch(int32_t sa, uint32_t ga, const ContactSide& a, int32_t sb, uint32_t gb,
             const ContactSide& b, double dt, ObjectWrench* on_a, ObjectWrench* on_b);
  // The step's end. Pairs no touch() met stay kept (a pair of objects asleep is met
  // again, unmoved, when one wakes) until a pair that has none needs the room: the one
  // met longest ago gives it up.
  void end_step() { ++step_; }

  // Pairs walked, and pairs answered from the cache, so far.
  int64_t walks() const { return walks_; }
  int64_t reuses() const { return reuses_; }

 private:
  struct LeafPair {
    int32_t a, b;
  };
  struct Entry {
    int32_t sa = -1, sb = -1;  // sa -1: free (never matches a pair)
    uint32_t ga = 0, gb = 0;
    RigidPose b_in_a;     // when walked
    double reach_b = 0.0;  // b's farthest leaf from its origin, metres
    int32_t count = 0;     // leaf pairs kept, from entry * kCachedLeafPairs
    int64_t met = -1;      // the step touch() last met it; -1: free
    PatchStick stick;      // the pair's static friction (object_contact.h)
  };

  std::vector<Entry> entries_;
  std::vector<LeafPair> leaves_;
  int64_t walks_ = 0, reuses_ = 0;
  int64_t step_ = 0;  // end_step() calls so far
};

}  // namespace frusta
