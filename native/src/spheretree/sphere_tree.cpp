// SPDX-License-Identifier: MIT
#include "spheretree/sphere_tree.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <cstring>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "geometry/contact_test.h"
#include "geometry/wide_contact_test.h"

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
static_assert(offsetof(TreeNode, center) == 0 && offsetof(TreeNode, radius) == 12,
              "a node's sphere is its first 16 bytes");

// The children [first, first + count) of a node that `test` keeps: bit k for child k.
// kOverhang: each child's radius grows by what stands out of it below (node_overhang).
template <bool kOverhang>
unsigned children_near(const WideSegmentTest& test, const SphereTree& tree, int32_t first,
                       int32_t count) {
  unsigned kept = 0;
#if defined(__GNUC__)
  const TreeNode* nodes = tree.nodes.data();
  const size_t size = tree.nodes.size();
  for (int32_t k = 0; k < count; k += 4) {
    // four nodes' spheres, read whole (past the last child too where the array goes on:
    // those lanes are dropped below) and turned into a register per coordinate; the
    // array's end checked once for the four, not lane by lane (a tenth of the culling)
    const size_t at = static_cast<size_t>(first + k);
    Floats4 sphere[4];
    Floats4 extra = {};
    if (at + 4 <= size) {
      for (int32_t i = 0; i < 4; ++i)
        std::memcpy(&sphere[i], &nodes[at + static_cast<size_t>(i)], sizeof(Floats4));
      if constexpr (kOverhang) std::memcpy(&extra, &tree.node_overhang[at], sizeof(Floats4));
    } else {
      for (int32_t i = 0; i < 4; ++i) {
        sphere[i] = Floats4{};
        if (at + static_cast<size_t>(i) >= size) continue;
        std::memcpy(&sphere[i], &nodes[at + static_cast<size_t>(i)], sizeof(Floats4));
        if constexpr (kOverhang) extra[i] = tree.node_overhang[at + static_cast<size_t>(i)];
      }
    }
    Floats4 x, y, z, radius;
    transpose(sphere, x, y, z, radius);
    kept |= lane_bits(test(x, y, z, kOverhang ? radius + extra : radius)) << k;
  }
#else
  for (int32_t k = 0; k < count; ++k) {
    const size_t node = static_cast<size_t>(first + k);
    const TreeNode& n = tree.nodes[node];
    const float radius = n.radius + (kOverhang ? tree.node_overhang[node] : 0.0f);
    kept |= static_cast<unsigned>(test(n.center[0], n.center[1], n.center[2], radius) != 0) << k;
  }
#endif
  static_assert(kMaxBranching < 32, "a bit per child");
  return kept & ((1u << count) - 1u);
}

// Where every child of `parent` is a leaf, the kept ones (bit k: child k) reported at once,
// in order, each written and counted by its bit: where most of a loose walk's hits are
// made. False, reporting nothing, where a child is not a leaf or the buffer lacks room for
// every child (the stack's way then reports them, counting those beyond the room).
bool report_leaf_children(const SphereTree& tree, const TreeNode& parent, unsigned kept,
                          BufferHits& out) {
  const TreeNode* child = &tree.nodes[static_cast<size_t>(parent.first)];
  int32_t inner = 0;
  for (int32_t k = 0; k < parent.count; ++k) inner |= child[k].count;
  if (inner != 0 || parent.count > out.capacity - out.count) return false;
  TreeHit* to = out.hits + out.count;
  int32_t reported = 0;
  for (int32_t k = 0; k < parent.count; ++k) {
    to[reported] = TreeHit{parent.first + k, child[k].first};
    reported += static_cast<int32_t>((kept >> k) & 1u);
  }
  out.count += reported;
  return true;
}

// walk_tree with may_touch, for less: the children of a node culled four at a time in
// single precision (which keeps every one may_touch keeps, and a few more), by their
// spheres and, under a cut, what stands out of them below (node_overhang: conservative
// for a child the cut stops at, which is tested as itself). With kExact every node the
// walk may report, a leaf or where the cut stops it, is then tested exactly: the same
// hits in the same order as walk_tree. Where the children are leaves (where most hits
// are made) each is then tested exactly at once, as walk_tree does: culling them first
// made the 10^5-leaf grasp's walks, which keep most of the leaves they test, slower.
// Without kExact the culling is the whole test (query_segment_loose). A leaf among inner
// children is culled by its node's sphere, which bounds it (the builder's rounding, the
// loader's check). Without kExact too, leaf children are reported as they are culled and
// the others pushed, neither with a branch per kept child: a closing grasp's detection,
// which had popped each leaf to report it and mispredicted on the kept bits, took 12 %
// less (10^4 leaves; the same hits in the same order).
template <bool kCuts, bool kExact>
TreeQueryStats walk_segment(const SphereTree& tree, const SegmentFrame& frame, double margin,
                            TreeCut cut, BufferHits& out) {
  TreeQueryStats stats;
  int32_t stack[kMaxTreeDepth * kMaxBranching + 1];
  int32_t levels[kCuts ? kMaxTreeDepth * kMaxBranching + 1 : 1];  // stack's, under a cut
  int top = 0;
  auto stops = [&](int32_t node, int32_t level) {
    return kCuts && tree.nodes[static_cast<size_t>(node)].count != 0 && cut.stops(tree, node, level);
  };
  auto exact = [&](int32_t node, bool stopping) {
    return may_touch(frame, walked_sphere(tree, node, stopping, kCuts ? cut : TreeCut()), margin);
  };
  auto push = [&](int32_t node, int32_t level) {
    if constexpr (kCuts) levels[top] = level;
    stack[top++] = node;
  };
  ++stats.visited;
  if (exact(0, stops(0, 0))) push(0, 0);
  const WideSegmentTest test(frame, margin);
  while (top > 0) {
    const int32_t node = stack[--top];
    const int32_t level = kCuts ? levels[top] : 0;
    const TreeNode& n = tree.nodes[static_cast<size_t>(node)];
    if (n.count == 0 || stops(node, level)) {
      out(TreeHit{node, n.count == 0 ? n.first : -1});
      ++stats.hits;
      continue;
    }
    stats.visited += n.count;
    // pushed last-first so they pop in array order
    if (kExact && tree.nodes[static_cast<size_t>(n.first)].count == 0) {
      for (int32_t c = n.first + n.count - 1; c >= n.first; --c)
        if (exact(c, stops(c, level + 1))) push(c, level + 1);
      continue;
    }
    const unsigned near = children_near<kCuts>(test, tree, n.first, n.count);
    if constexpr (!kExact) {
      const int32_t before = out.count;
      if (report_leaf_children(tree, n, near, out)) {
        stats.hits += out.count - before;
        continue;
      }
      // every child written, and kept by its bit; the stack has room for a node's children
      // above its ancestors' waiting siblings (depth and branching bounded by the loader)
      assert(top + n.count <= kMaxTreeDepth * kMaxBranching + 1);
      for (int32_t c = n.first + n.count - 1; c >= n.first; --c) {
        if constexpr (kCuts) levels[top] = level + 1;
        stack[top] = c;
        top += static_cast<int>((near >> (c - n.first)) & 1u);
      }
      continue;
    }
    for (unsigned kept = near; kept != 0;) {
      const int k = highest_bit(kept);
      kept &= ~(1u << k);
      const int32_t child = n.first + k;
      const bool stopping = stops(child, level + 1);
      if (kExact && (stopping || tree.nodes[static_cast<size_t>(child)].count == 0) &&
          !exact(child, stopping))
        continue;
      push(child, level + 1);
    }
  }
  return stats;
}

template <bool kExact>
TreeQueryStats segment_query(const SphereTree& tree, const SegmentFrame& frame, double margin,
                             TreeCut cut, TreeHit* hits, int32_t capacity) {
  BufferHits out{hits, capacity};
  if (tree.empty()) return {};
  assert(!cut.cuts() || tree.node_overhang.size() == tree.nodes.size());  // built or loaded
  return cut.cuts() ? walk_segment<true, kExact>(tree, frame, margin, cut, out)
                    : walk_segment<false, kExact>(tree, frame, margin, cut, out);
}

}  // namespace

TreeQueryStats query_segment(const SphereTree& tree, const SegmentFrame& frame, double margin,
                             TreeCut cut, TreeHit* hits, int32_t capacity) {
  return segment_query<true>(tree, frame, margin, cut, hits, capacity);
}

TreeQueryStats query_segment_loose(const SphereTree& tree, const SegmentFrame& frame, double margin,
                                   TreeCut cut, TreeHit* hits, int32_t capacity) {
  return segment_query<false>(tree, frame, margin, cut, hits, capacity);
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
