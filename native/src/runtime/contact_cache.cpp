// SPDX-License-Identifier: MIT
#include "runtime/contact_cache.h"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "spheretree/tree_pairs.h"

namespace frusta {

namespace {

// How far any leaf of b (within `reach` of its origin) may have moved against a between
// two relative poses: the shift, plus the rotation's change times the reach (the
// Frobenius norm bounds the change's largest stretch).
double moved(const RigidPose& then, const RigidPose& now, double reach) {
  double turn = 0.0;
  for (int c = 0; c < 3; ++c) {
    const vec3 d = now.rotation[c] - then.rotation[c];
    turn += glm::dot(d, d);
  }
  return glm::length(now.position - then.position) + std::sqrt(turn) * reach;
}

}  // namespace

ContactCache::ContactCache()
    : entries_(kCachedPairs), leaves_(static_cast<size_t>(kCachedPairs) * kCachedLeafPairs) {}

bool ContactCache::touch(int32_t sa, uint32_t ga, const ContactSide& a, int32_t sb, uint32_t gb,
                         const ContactSide& b, double dt, ObjectWrench* on_a, ObjectWrench* on_b) {
  // a pair is met from either side (from the awake one, or the lower slot of two awake):
  // one entry for both, its walk and its stick kept as the objects fall asleep and wake
  if (sb < sa) return touch(sb, gb, b, sa, ga, a, dt, on_b, on_a);
  const RigidPose now = relative_pose(a.def->pose, b.def->pose);
  Entry* entry = nullptr;
  Entry* room = nullptr;  // the entry met longest ago (a free one never), not this step
  for (Entry& e : entries_) {
    if (e.sa == sa && e.sb == sb && e.ga == ga && e.gb == gb) entry = &e;
    if (e.met < step_ && (!room || e.met < room->met)) room = &e;
  }
  ContactPatchSums patch;
  if (entry && moved(entry->b_in_a, now, entry->reach_b) <= kMargin) {
    ++reuses_;
    entry->met = step_;
    const LeafPair* kept = &leaves_[static_cast<size_t>(entry - entries_.data()) * kCachedLeafPairs];
    for (int32_t i = 0; i < entry->count; ++i) {
      const Sphere& la = a.tree->leaves[static_cast<size_t>(kept[i].a)];
      const Sphere& local = b.tree->leaves[static_cast<size_t>(kept[i].b)];
      // as the walk places b's leaves, so the sums are the walk's
      patch.add(la, Sphere{now.position + now.rotation * local.center, local.radius});
    }
    return add_patch_wrench(patch, a, b, dt, &entry->stick, on_a, on_b);
  }
  ++walks_;
  // a pair without an entry sticks afresh (and, without room, every step)
  PatchStick stick = entry ? entry->stick : PatchStick{};
  if (!entry) entry = room;  // none: every entry met this step, so this pair is walked
  LeafPair* kept =
      entry ? &leaves_[static_cast<size_t>(entry - entries_.data()) * kCachedLeafPairs] : nullptr;
  int32_t count = 0;
  walk_overlapping_leaves(
      *a.tree, *b.tree, now,
      [&](int32_t ia, int32_t ib, const Sphere& la, const Sphere& lb) {
        patch.add(la, lb);
        if (count < kCachedLeafPairs && kept) kept[count] = {ia, ib};
        ++count;
      },
      kMargin);
  const bool touching = add_patch_wrench(patch, a, b, dt, &stick, on_a, on_b);
  if (entry) {
    if (count <= kCachedLeafPairs) {
      const Sphere root = b.tree->node_sphere(0);
      *entry =
          Entry{sa, sb, ga, gb, now, glm::length(root.center) + root.radius, count, step_, stick};
    } else {
      *entry = Entry{};  // too many to keep: free
    }
  }
  return touching;
}

}  // namespace frusta
