// SPDX-License-Identifier: MIT
// An object as a sphere tree (seed [0012], [0117]): the leaves are its numbered
// contact spheres, each inner node bounds every leaf below it. Nodes live in one
// flat array with each node's children contiguous, so a query walks memory forward.
#pragma once

#include <cassert>
#include <cstdint>
#include <vector>

#include <glm/mat3x3.hpp>
#if defined(_MSC_VER)
#include <intrin.h>  // _BitScanForward64, _BitScanReverse
#endif

#include "geometry/segment_frame.h"
#include "geometry/types.h"
#include "spheretree/tree_limits.h"

namespace frusta {

// 24 bytes. Floats suffice in the object's own frame (0.1 um at 1 m); bounds are
// rounded outwards when stored so a culled node can never hide a touching leaf.
struct TreeNode {
  float center[3];
  float radius;
  int32_t first;  // inner: index of the first child; leaf: the leaf's number
  int32_t count;  // inner: number of children (> 0); leaf: 0
};

struct SphereTree {
  std::vector<TreeNode> nodes;  // nodes[0] is the root; children follow their parent
  std::vector<Sphere> leaves;   // in the caller's numbering, never reordered
  std::vector<float> node_error;  // per node, metres its sphere stands out of its leaves
                                  // (compute_node_errors; 0 for a leaf)
  // per node, metres the spheres of the inner nodes beneath it stick out of its own (a
  // node bounds its leaves, not its children's spheres), which a walk under a cut must
  // reach (compute_node_errors; 0 for a leaf)
  std::vector<float> node_overhang;
  int32_t branching = 0;
  int32_t depth = 0;  // levels below the root; a lone leaf has depth 0

  bool empty() const { return nodes.empty(); }
  Sphere node_sphere(int32_t node) const {  // inline: read per node of every walk
    const TreeNode& n = nodes[static_cast<size_t>(node)];
    return {vec3(n.center[0], n.center[1], n.center[2]), n.radius};
  }
};

// What a query reports: a node whose sphere is within reach, and at the deepest
// level allowed, a leaf (leaf >= 0) or an inner node standing in for its subtree.
struct TreeHit {
  int32_t node;
  int32_t leaf;  // -1 when the hit is an inner node cut off by the query's TreeCut
};

// Where a walk stops descending: at a leaf, at max_level (-1: no level), or at an inner
// node that stands out of its leaves by no more than max_error (0: none; the tree's
// node_error), which then stands in for its subtree: the level of detail an error budget
// buys. A level converts to a cut, so callers may pass one.
struct TreeCut {
  TreeCut(int32_t level = -1, double error = 0.0) : max_level(level), max_error(error) {}  // NOLINT
  int32_t max_level;
  double max_error;

  bool stops(const SphereTree& tree, int32_t node, int32_t level) const {
    assert(max_error <= 0.0 || tree.node_error.size() == tree.nodes.size());  // built or loaded
    return level == max_level ||
           (max_error > 0.0 && tree.node_error[static_cast<size_t>(node)] <= max_error);
  }
  bool cuts() const { return max_level >= 0 || max_error > 0.0; }  // may stop above a leaf
};

// The sphere a walk tests a node by: a leaf's, or that of a node where the walk stops,
// as it is; a node the walk goes on through stands for everything below it that may be
// reported, which under a cut includes inner nodes sticking out of it (node_overhang).
// Without that, a node standing in was missed by a small margin and found by a larger
// one: a hand held on a level of detail found nothing near, moved in, and was pushed
// out again some steps later, its contacts and forces coming and going.
inline Sphere walked_sphere(const SphereTree& tree, int32_t node, bool stops, TreeCut cut) {
  const TreeNode& n = tree.nodes[static_cast<size_t>(node)];
  if (n.count == 0) return tree.leaves[static_cast<size_t>(n.first)];
  Sphere s = tree.node_sphere(node);
  if (!stops && cut.cuts()) {
    assert(tree.node_overhang.size() == tree.nodes.size());  // built or loaded
    s.radius += static_cast<double>(tree.node_overhang[static_cast<size_t>(node)]);
  }
  return s;
}

struct TreeQueryStats {
  int32_t visited = 0;  // node tests performed
  int32_t hits = 0;     // hits found, including those beyond capacity
};

// Rigid pose of an object: world = rotation * local + position.
struct RigidPose {
  vec3 position{0.0};
  glm::dmat3 rotation{1.0};
};

namespace tree_detail {
// walk_tree's loop, with the cut's tests compiled in only where it can stop the walk
// above a leaf: a walk to the leaves (the solver's default) pays for none of them, which
// were 15 % of a segment walk's instructions on the 10^4-leaf grasp
template <bool kCuts, class Touches, class Emit>
TreeQueryStats walk_tree(const SphereTree& tree, Touches& touches, TreeCut cut, Emit& emit) {
  TreeQueryStats stats;
  struct Place {  // where a node stands under a cut
    int32_t level;
    bool stops;
  };
  int32_t stack[kMaxTreeDepth * kMaxBranching + 1];
  Place places[kCuts ? kMaxTreeDepth * kMaxBranching + 1 : 1];  // stack's, under a cut
  int top = 0;
  // A node is tested as its parent opens and pushed only if it passes: its siblings'
  // tests then run back to back, which the processor overlaps (a walk of a 10^4-leaf
  // grasp's segment 7 % faster than testing each node as it is popped)
  auto visit = [&](int32_t node, int32_t level) {
    ++stats.visited;
    const bool stops =
        kCuts && tree.nodes[static_cast<size_t>(node)].count != 0 && cut.stops(tree, node, level);
    if (!touches(walked_sphere(tree, node, stops, kCuts ? cut : TreeCut()))) return;
    if constexpr (kCuts) places[top] = {level, stops};
    stack[top++] = node;
  };
  visit(0, 0);
  while (top > 0) {
    const int32_t node = stack[--top];
    Place place{0, false};
    if constexpr (kCuts) place = places[top];
    const TreeNode& n = tree.nodes[static_cast<size_t>(node)];
    if (n.count == 0 || place.stops) {
      emit(TreeHit{node, n.count == 0 ? n.first : -1});
      ++stats.hits;
      continue;
    }
    // children pushed last-first so they pop in array order
    for (int32_t c = n.first + n.count - 1; c >= n.first; --c) visit(c, place.level + 1);
  }
  return stats;
}
}  // namespace tree_detail

// Depth-first walk reporting, in node order, every node the predicate accepts where
// the cut stops the walk (or at a leaf), to emit(TreeHit). Leaves are tested as
// their exact spheres, inner nodes as their outward-rounded bounds, so the result
// equals a scan of every leaf. The stack is bounded by the tree limits and lives on
// the thread's stack: the walk itself allocates nothing.
template <class Touches, class Emit>
TreeQueryStats walk_tree(const SphereTree& tree, Touches touches, TreeCut cut, Emit emit) {
  if (tree.empty()) return {};
  return cut.cuts() ? tree_detail::walk_tree<true>(tree, touches, cut, emit)
                    : tree_detail::walk_tree<false>(tree, touches, cut, emit);
}

// Index of the lowest set bit of a non-zero mask.
inline int lowest_bit(uint64_t mask) {
#if defined(_MSC_VER)
  unsigned long index;
  _BitScanForward64(&index, mask);
  return static_cast<int>(index);
#else
  return __builtin_ctzll(mask);
#endif
}

// Index of the highest set bit of a non-zero mask.
inline int highest_bit(uint32_t mask) {
#if defined(_MSC_VER)
  unsigned long index;
  _BitScanReverse(&index, mask);
  return static_cast<int>(index);
#else
  return 31 - __builtin_clz(mask);
#endif
}

// The most probes one walk_tree_masked carries: the bits of its masks.
constexpr int kMaxProbes = 64;

// walk_tree for up to kMaxProbes probes at once (a body made of many spheres): one descent
// carrying, per node, the probes whose own walk would reach it. touches(k, sphere) is
// probe k's test; `near(sphere)` a cheap test that must be false only where every
// probe's is (a bound around them all), asked first so most far nodes cost one test.
// emit(TreeHit, mask, sphere) gets every node that walk_tree(probe k) would emit, for each
// k in mask, in node order, with the sphere tested (the leaf's, or the cut node's); `probes` are the ones to walk (their own bound tests passed).
// `visited` counts nodes popped, as walk_tree's (one walk here, not one per probe).
template <class Near, class Touches, class Emit>
TreeQueryStats walk_tree_masked(const SphereTree& tree, uint64_t probes, Near near, Touches touches,
                                TreeCut cut, Emit emit) {
  TreeQueryStats stats;
  if (tree.empty() || probes == 0) return stats;
  struct Entry {
    int32_t node, level;
    uint64_t probes;  // those that reached the parent
  };
  Entry stack[kMaxTreeDepth * kMaxBranching + 1];
  int top = 0;
  stack[top++] = {0, 0, probes};
  while (top > 0) {
    const Entry e = stack[--top];
    const TreeNode& n = tree.nodes[static_cast<size_t>(e.node)];
    ++stats.visited;
    const bool leaf = n.count == 0;
    const bool stops = !leaf && cut.stops(tree, e.node, e.level);
    const Sphere sphere = walked_sphere(tree, e.node, stops, cut);
    if (!near(sphere)) continue;
    uint64_t reached = 0;
    for (uint64_t rest = e.probes; rest != 0; rest &= rest - 1) {
      const int k = lowest_bit(rest);
      if (touches(k, sphere)) reached |= uint64_t{1} << k;
    }
    if (reached == 0) continue;
    if (leaf || stops) {
      emit(TreeHit{e.node, leaf ? n.first : -1}, reached, sphere);
      ++stats.hits;
      continue;
    }
    for (int32_t c = n.count - 1; c >= 0; --c) stack[top++] = {n.first + c, e.level + 1, reached};
  }
  return stats;
}

// b's pose in a's frame.
RigidPose relative_pose(const RigidPose& a, const RigidPose& b);

// Express a world segment in the object's frame (the tree is never rebuilt).
Segment to_object_frame(const RigidPose& pose, const Segment& world);
Sphere to_object_frame(const RigidPose& pose, const Sphere& world);

// All nodes within `margin` of the segment solid (frame in the object's frame), down
// to the cut (-1: leaves). Writes at most capacity hits; allocates nothing.
TreeQueryStats query_segment(const SphereTree& tree, const SegmentFrame& frame, double margin,
                             TreeCut cut, TreeHit* hits, int32_t capacity);

// The same, its hits tested in single precision only: every node query_segment reports,
// in its order, and perhaps some beyond the margin (by a few parts in 10^5 of the sizes
// tested, a node the cut stops at by its node_overhang too), for a caller that measures
// each hit anyway. A fingertip's walk into a shell (bench spheretree): 2.1 against 4.0 us
// at 10^4 leaves, 14.7 against 22.4 us at 10^5, about one hit in 3,000 more.
TreeQueryStats query_segment_loose(const SphereTree& tree, const SegmentFrame& frame, double margin,
                                   TreeCut cut, TreeHit* hits, int32_t capacity);

// The same for a sphere (e.g. a palm sphere).
TreeQueryStats query_sphere(const SphereTree& tree, const Sphere& sphere, double margin,
                            TreeCut cut, TreeHit* hits, int32_t capacity);

// Signed distance from a point to the union of the leaves (negative inside one):
// branch and bound over the tree, for measuring how well leaves fit a surface.
double distance_to_leaves(const SphereTree& tree, const vec3& point);

}  // namespace frusta
