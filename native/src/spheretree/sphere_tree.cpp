// SPDX-License-Identifier: MIT
#include "spheretree/sphere_tree.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "geometry/contact_test.h"

namespace frusta {

RigidPose relative_pose(const RigidPose& a, const RigidPose& b) {
  const glm::dmat3 to_a = glm::transpose(a.rotation);
  return {to_a * (b.position - a.position), to_a * b.rotation};
}

Segment to_object_frame(const RigidPose& pose, const Segment& world) {
  const glm::dmat3 inverse = glm::transpose(pose.rotation);
  return {inverse * (world.proximal - pose.position), inverse * (world.distal - pose.position),
          world.proximal_radius, world.distal_radius};
}

Sphere to_object_frame(const RigidPose& pose, const Sphere& world) {
  return {glm::transpose(pose.rotation) * (world.center - pose.position), world.radius};
}

namespace {
// collects hits into a caller buffer, counting those beyond its capacity
struct BufferHits {
  TreeHit* hits;
  int32_t capacity;
  int32_t count = 0;
  void operator()(const TreeHit& h) {
    if (count < capacity) hits[count] = h;
    ++count;
  }
};
}  // namespace

TreeQueryStats query_segment(const SphereTree& tree, const SegmentFrame& frame, double margin,
                             TreeCut cut, TreeHit* hits, int32_t capacity) {
  return walk_tree(tree, [&](const Sphere& s) { return may_touch(frame, s, margin); }, cut,
                   BufferHits{hits, capacity});
}

TreeQueryStats query_sphere(const SphereTree& tree, const Sphere& sphere, double margin,
                            TreeCut cut, TreeHit* hits, int32_t capacity) {
  return walk_tree(tree, [&](const Sphere& s) { return may_touch_sphere(sphere, s, margin); },
                   cut, BufferHits{hits, capacity});
}

double distance_to_leaves(const SphereTree& tree, const vec3& point) {
  double best = INFINITY;
  if (tree.empty()) return best;
  int32_t stack[kMaxTreeDepth * kMaxBranching + 1];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const int32_t index = stack[--top];
    const TreeNode& n = tree.nodes[static_cast<size_t>(index)];
    if (n.count == 0) {
      const Sphere& leaf = tree.leaves[static_cast<size_t>(n.first)];
      best = std::min(best, glm::length(point - leaf.center) - leaf.radius);
      continue;
    }
    // every leaf below lies inside the bound, so none is nearer than its surface
    const Sphere bound = tree.node_sphere(index);
    if (glm::length(point - bound.center) - bound.radius >= best) continue;
    for (int32_t c = n.count - 1; c >= 0; --c) stack[top++] = n.first + c;
  }
  return best;
}

}  // namespace frusta
