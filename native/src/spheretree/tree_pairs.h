// SPDX-License-Identifier: MIT
// Where two objects' trees overlap: every pair of leaves, one from each tree, whose
// spheres overlap, found by a dual walk that descends the larger of two touching nodes
// (so neither tree is walked where the other is far).
#pragma once

#include <glm/matrix.hpp>

#include "spheretree/sphere_tree.h"

namespace frusta {

// `b_in_a`: b's pose in a's frame. Reports emit(leaf_a, leaf_b, sphere_a, sphere_b) (the
// leaves' numbers, and their spheres in a's frame) for each pair closer than `margin`
// (>= 0; 0: overlapping), in an order that does not depend on the margin; returns the
// node pairs tested. The stack is bounded by the tree limits and lives on the thread's stack:
// the walk allocates nothing.
template <class Emit>
int32_t walk_overlapping_leaves(const SphereTree& a, const SphereTree& b, const RigidPose& b_in_a,
                                Emit emit, double margin = 0.0) {
  if (a.empty() || b.empty()) return 0;
  auto sphere_a = [&](int32_t node) {
    const TreeNode& n = a.nodes[static_cast<size_t>(node)];
    return n.count == 0 ? a.leaves[static_cast<size_t>(n.first)] : a.node_sphere(node);
  };
  auto sphere_b = [&](int32_t node) {
    const TreeNode& n = b.nodes[static_cast<size_t>(node)];
    const Sphere s = n.count == 0 ? b.leaves[static_cast<size_t>(n.first)] : b.node_sphere(node);
    return Sphere{b_in_a.position + b_in_a.rotation * s.center, s.radius};
  };
  struct Entry {
    int32_t a, b;
  };
  // every pair on the stack overlaps: a pair is tested as its parent pair opens, against
  // the side that stays, whose sphere (b's placed in a's frame) is made once for all of
  // the children, and pushed only if it passes. Each pop pushes at most one node's
  // children, and a pair descends one tree a level: at most (depth_a + depth_b) levels of
  // kMaxBranching - 1 entries left behind
  Entry stack[2 * kMaxTreeDepth * kMaxBranching + 1];
  int top = 0;
  auto overlap = [margin](const Sphere& sa, const Sphere& sb) {
    const vec3 d = sa.center - sb.center;
    const double reach = sa.radius + sb.radius + margin;
    return glm::dot(d, d) < reach * reach;
  };
  int32_t tested = 1;
  if (overlap(sphere_a(0), sphere_b(0))) stack[top++] = {0, 0};
  while (top > 0) {
    const Entry e = stack[--top];
    const TreeNode& na = a.nodes[static_cast<size_t>(e.a)];
    const TreeNode& nb = b.nodes[static_cast<size_t>(e.b)];
    if (na.count == 0 && nb.count == 0) {
      emit(na.first, nb.first, sphere_a(e.a), sphere_b(e.b));
      continue;
    }
    // descend a where it is an inner node and no smaller than b (or b is a leaf); the
    // children pushed last-first so that they pop in array order
    const Sphere sa = sphere_a(e.a), sb = sphere_b(e.b);
    if (na.count > 0 && (nb.count == 0 || sa.radius >= sb.radius)) {
      tested += na.count;
      for (int32_t c = na.first + na.count - 1; c >= na.first; --c)
        if (overlap(sphere_a(c), sb)) stack[top++] = {c, e.b};
    } else {
      tested += nb.count;
      for (int32_t c = nb.first + nb.count - 1; c >= nb.first; --c)
        if (overlap(sa, sphere_b(c))) stack[top++] = {e.a, c};
    }
  }
  return tested;
}

}  // namespace frusta
