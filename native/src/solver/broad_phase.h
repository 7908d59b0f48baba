// SPDX-License-Identifier: MIT
// A broad phase over a scene's objects: a dynamic bounding-volume tree in the manner of
// Box2D's (erincatto/box2d:src/dynamic_tree.c). Each object is a leaf holding its world
// bound's box fattened by kFatMargin, so that an object that moves a little (held, or
// dynamic) is re-inserted only when it leaves its fat box; inner nodes hold the union of
// their children and are kept balanced by rotations, so that a query by box visits
// O(log n + hits) nodes and objects far from the hands cost a step nothing (issue 21).
//
// Every node comes from a pool sized at construction for `capacity` leaves: nothing is
// allocated afterwards. Not thread-safe: one owner (the world's stepping side).
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/types.h"

namespace frusta {

struct Aabb {
  vec3 lower{0.0};
  vec3 upper{0.0};
};

inline bool overlaps(const Aabb& a, const Aabb& b) {
  return a.lower.x <= b.upper.x && b.lower.x <= a.upper.x && a.lower.y <= b.upper.y &&
         b.lower.y <= a.upper.y && a.lower.z <= b.upper.z && b.lower.z <= a.upper.z;
}
inline bool contains(const Aabb& outer, const Aabb& inner) {
  return outer.lower.x <= inner.lower.x && outer.lower.y <= inner.lower.y &&
         outer.lower.z <= inner.lower.z && inner.upper.x <= outer.upper.x &&
         inner.upper.y <= outer.upper.y && inner.upper.z <= outer.upper.z;
}
// The box around a sphere.
inline Aabb sphere_box(const Sphere& s) { return {s.center - s.radius, s.center + s.radius}; }

// Which of a step's objects may lie in a box: the solver asks it for each sub-step,
// instead of looking at every object (hand_solver.h).
class ObjectFinder {
 public:
  // Write the indices (into the step's object array) of every object whose bound meets
  // `box`, and perhaps a few more, into out[0, capacity); return how many there are
  // (more than capacity: call again with room for them).
  virtual int32_t find(const Aabb& box, int32_t* out, int32_t capacity) const = 0;

 protected:
  ~ObjectFinder() = default;
};

class BroadPhase {
 public:
  // How far a leaf's box reaches past its object's bound: a move of up to this much
  // costs no re-insertion. Metres.
  static constexpr double kFatMargin = 0.01;
  static constexpr int32_t kNull = -1;

  explicit BroadPhase(int32_t capacity);

  // A leaf for `box` (fattened here), carrying `user`; kNull when `capacity` leaves
  // exist already.
  int32_t create_proxy(const Aabb& box, int32_t user);
  void destroy_proxy(int32_t proxy);
  // The object's bound is now `box`: re-inserted (fattened again) only when it left the
  // leaf's fat box. Returns whether it was.
  bool move_proxy(int32_t proxy, const Aabb& box);

  // Call visit(user) for every leaf whose fat box meets `box`.
  template <class Visit>
  void query(const Aabb& box, Visit&& visit) const;

  int32_t user(int32_t proxy) const { return nodes_[static_cast<size_t>(proxy)].user; }
  const Aabb& fat_box(int32_t proxy) const { return nodes_[static_cast<size_t>(proxy)].box; }
  int32_t proxy_count() const { return proxy_count_; }
  int32_t capacity() const { return capacity_; }
  // 0 for an empty tree or a single leaf.
  int32_t height() const { return root_ == kNull ? 0 : nodes_[static_cast<size_t>(root_)].height; }
  // The whole structure checked (parents, heights, each box the union of its
  // children's, the free list, the query's stack bound): for tests.
  bool valid() const;

 private:
  struct Node {
    Aabb box;
    int32_t parent = kNull;  // or the next free node
    int32_t child1 = kNull, child2 = kNull;  // kNull for a leaf
    int32_t height = -1;     // leaf 0; free -1
    int32_t user = -1;
    bool leaf() const { return child1 == kNull; }
  };

  int32_t allocate();
  void release(int32_t node);
  void insert_leaf(int32_t leaf);
  void remove_leaf(int32_t leaf);
  int32_t balance(int32_t a);
  int32_t check(int32_t node, int32_t parent, int32_t* leaves) const;

  std::vector<Node> nodes_;
  int32_t capacity_;
  int32_t root_ = kNull;
  int32_t free_ = kNull;
  int32_t proxy_count_ = 0;
  // the query's stack: a depth-first walk holds at most height + 1 nodes, and the
  // rotations keep a tree of 2^16 leaves about 1.44 * 16 deep (valid() checks the bound)
  static constexpr int kStack = 256;
};

template <class Visit>
void BroadPhase::query(const Aabb& box, Visit&& visit) const {
  if (root_ == kNull) return;
  int32_t stack[kStack];
  int count = 0;
  stack[count++] = root_;
  while (count > 0) {
    const Node& node = nodes_[static_cast<size_t>(stack[--count])];
    if (!overlaps(node.box, box)) continue;
    if (node.leaf()) {
      visit(node.user);
    } else {
      stack[count++] = node.child1;  // the height bound keeps this within kStack
      stack[count++] = node.child2;
    }
  }
}

}  // namespace frusta
