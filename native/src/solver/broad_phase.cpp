// SPDX-License-Identifier: MIT
#include "solver/broad_phase.h"

#include <algorithm>
#include <cassert>

#include <glm/common.hpp>

namespace frusta {

namespace {

Aabb merged(const Aabb& a, const Aabb& b) { return {glm::min(a.lower, b.lower), glm::max(a.upper, b.upper)}; }

// Half the surface area: the cost of a box in the insertion heuristic.
double area(const Aabb& a) {
  const vec3 d = a.upper - a.lower;
  return d.x * d.y + d.y * d.z + d.z * d.x;
}

}  // namespace

BroadPhase::BroadPhase(int32_t capacity)
    : nodes_(static_cast<size_t>(std::max(1, 2 * capacity - 1))), capacity_(capacity) {
  // every node on the free list, in order
  for (size_t i = 0; i < nodes_.size(); ++i)
    nodes_[i].parent = i + 1 < nodes_.size() ? static_cast<int32_t>(i + 1) : kNull;
  free_ = 0;
}

int32_t BroadPhase::allocate() {
  assert(free_ != kNull);  // 2 * capacity - 1 nodes hold capacity leaves
  const int32_t node = free_;
  Node& n = nodes_[static_cast<size_t>(node)];
  free_ = n.parent;
  n = Node{};
  n.height = 0;
  return node;
}

void BroadPhase::release(int32_t node) {
  Node& n = nodes_[static_cast<size_t>(node)];
  n = Node{};
  n.parent = free_;
  free_ = node;
}

int32_t BroadPhase::create_proxy(const Aabb& box, int32_t user) {
  if (proxy_count_ >= capacity_) return kNull;
  const int32_t leaf = allocate();
  Node& n = nodes_[static_cast<size_t>(leaf)];
  n.box = {box.lower - kFatMargin, box.upper + kFatMargin};
  n.user = user;
  insert_leaf(leaf);
  ++proxy_count_;
  return leaf;
}

void BroadPhase::destroy_proxy(int32_t proxy) {
  assert(nodes_[static_cast<size_t>(proxy)].leaf() && nodes_[static_cast<size_t>(proxy)].height == 0);
  remove_leaf(proxy);
  release(proxy);
  --proxy_count_;
}

bool BroadPhase::move_proxy(int32_t proxy, const Aabb& box) {
  Node& n = nodes_[static_cast<size_t>(proxy)];
  if (contains(n.box, box)) return false;
  remove_leaf(proxy);
  n.box = {box.lower - kFatMargin, box.upper + kFatMargin};
  insert_leaf(proxy);
  return true;
}

void BroadPhase::insert_leaf(int32_t leaf) {
  if (root_ == kNull) {
    root_ = leaf;
    nodes_[static_cast<size_t>(leaf)].parent = kNull;
    return;
  }
  // the best sibling by the surface-area heuristic: descend while a child costs less
  // than pairing with this node (Box2D v2.4's descent)
  const Aabb box = nodes_[static_cast<size_t>(leaf)].box;
  int32_t index = root_;
  while (!nodes_[static_cast<size_t>(index)].leaf()) {
    const Node& node = nodes_[static_cast<size_t>(index)];
    const double node_area = area(node.box);
    const double combined = area(merged(node.box, box));
    const double cost = 2.0 * combined;                    // a new parent for node and leaf
    const double inheritance = 2.0 * (combined - node_area);  // every box below grows
    auto descend_cost = [&](int32_t child) {
      const Node& c = nodes_[static_cast<size_t>(child)];
      const double grown = area(merged(box, c.box));
      return c.leaf() ? grown + inheritance : grown - area(c.box) + inheritance;
    };
    const double cost1 = descend_cost(node.child1), cost2 = descend_cost(node.child2);
    if (cost < cost1 && cost < cost2) break;
    index = cost1 < cost2 ? node.child1 : node.child2;
  }
  const int32_t sibling = index;

  // a new parent for the sibling and the leaf
  const int32_t old_parent = nodes_[static_cast<size_t>(sibling)].parent;
  const int32_t parent = allocate();
  {
    Node& p = nodes_[static_cast<size_t>(parent)];
    p.parent = old_parent;
    p.box = merged(box, nodes_[static_cast<size_t>(sibling)].box);
    p.height = nodes_[static_cast<size_t>(sibling)].height + 1;
    p.child1 = sibling;
    p.child2 = leaf;
  }
  if (old_parent != kNull) {
    Node& op = nodes_[static_cast<size_t>(old_parent)];
    (op.child1 == sibling ? op.child1 : op.child2) = parent;
  } else {
    root_ = parent;
  }
  nodes_[static_cast<size_t>(sibling)].parent = parent;
  nodes_[static_cast<size_t>(leaf)].parent = parent;

  // up to the root: balance, then refit heights and boxes
  for (index = parent; index != kNull; index = nodes_[static_cast<size_t>(index)].parent) {
    index = balance(index);
    Node& n = nodes_[static_cast<size_t>(index)];
    const Node& c1 = nodes_[static_cast<size_t>(n.child1)];
    const Node& c2 = nodes_[static_cast<size_t>(n.child2)];
    n.height = 1 + std::max(c1.height, c2.height);
    n.box = merged(c1.box, c2.box);
  }
}

void BroadPhase::remove_leaf(int32_t leaf) {
  if (leaf == root_) {
    root_ = kNull;
    return;
  }
  const int32_t parent = nodes_[static_cast<size_t>(leaf)].parent;
  const Node& p = nodes_[static_cast<size_t>(parent)];
  const int32_t grand = p.parent;
  const int32_t sibling = p.child1 == leaf ? p.child2 : p.child1;
  release(parent);
  nodes_[static_cast<size_t>(sibling)].parent = grand;
  if (grand == kNull) {
    root_ = sibling;
    return;
  }
  Node& g = nodes_[static_cast<size_t>(grand)];
  (g.child1 == parent ? g.child1 : g.child2) = sibling;
  for (int32_t index = grand; index != kNull; index = nodes_[static_cast<size_t>(index)].parent) {
    index = balance(index);
    Node& n = nodes_[static_cast<size_t>(index)];
    const Node& c1 = nodes_[static_cast<size_t>(n.child1)];
    const Node& c2 = nodes_[static_cast<size_t>(n.child2)];
    n.box = merged(c1.box, c2.box);
    n.height = 1 + std::max(c1.height, c2.height);
  }
}

// A left or right rotation when a's subtrees differ in height by more than one
// (Box2D v2.4's b2DynamicTree::Balance); returns the subtree's new root.
int32_t BroadPhase::balance(int32_t ia) {
  Node& a = nodes_[static_cast<size_t>(ia)];
  if (a.leaf() || a.height < 2) return ia;
  const int32_t ib = a.child1, ic = a.child2;
  Node& b = nodes_[static_cast<size_t>(ib)];
  Node& c = nodes_[static_cast<size_t>(ic)];
  const int32_t tilt = c.height - b.height;

  // raise the taller child `up` over a; `other` is a's other child
  auto rotate = [&](int32_t iup, int32_t iother) {
    Node& up = nodes_[static_cast<size_t>(iup)];
    Node& other = nodes_[static_cast<size_t>(iother)];
    const int32_t if_ = up.child1, ig = up.child2;
    Node& f = nodes_[static_cast<size_t>(if_)];
    Node& g = nodes_[static_cast<size_t>(ig)];
    // up takes a's place
    up.child1 = ia;
    up.parent = a.parent;
    a.parent = iup;
    if (up.parent != kNull) {
      Node& pp = nodes_[static_cast<size_t>(up.parent)];
      (pp.child1 == ia ? pp.child1 : pp.child2) = iup;
    } else {
      root_ = iup;
    }
    // the taller of up's children stays with up, the shorter goes to a
    const bool f_taller = f.height > g.height;
    const int32_t keep = f_taller ? if_ : ig, give = f_taller ? ig : if_;
    Node& k = nodes_[static_cast<size_t>(keep)];
    Node& gv = nodes_[static_cast<size_t>(give)];
    up.child2 = keep;
    if (a.child1 == iup) a.child1 = give; else a.child2 = give;
    gv.parent = ia;
    a.box = merged(other.box, gv.box);
    up.box = merged(a.box, k.box);
    a.height = 1 + std::max(other.height, gv.height);
    up.height = 1 + std::max(a.height, k.height);
    return iup;
  };
  if (tilt > 1) return rotate(ic, ib);
  if (tilt < -1) return rotate(ib, ic);
  return ia;
}

int32_t BroadPhase::check(int32_t index, int32_t parent, int32_t* leaves) const {
  const Node& n = nodes_[static_cast<size_t>(index)];
  if (n.parent != parent) return -1;
  if (n.leaf()) {
    ++*leaves;
    return n.height == 0 && n.child2 == kNull ? 0 : -1;
  }
  const int32_t h1 = check(n.child1, index, leaves), h2 = check(n.child2, index, leaves);
  if (h1 < 0 || h2 < 0 || n.height != 1 + std::max(h1, h2)) return -1;
  const Aabb both = merged(nodes_[static_cast<size_t>(n.child1)].box, nodes_[static_cast<size_t>(n.child2)].box);
  if (both.lower != n.box.lower || both.upper != n.box.upper) return -1;
  return n.height;
}

bool BroadPhase::valid() const {
  int32_t leaves = 0;
  if (root_ != kNull && check(root_, kNull, &leaves) < 0) return false;
  if (leaves != proxy_count_ || height() + 1 > kStack) return false;
  // every node is in the tree (2 * leaves - 1 of them) or on the free list
  int32_t free_count = 0;
  for (int32_t i = free_; i != kNull; i = nodes_[static_cast<size_t>(i)].parent) {
    if (nodes_[static_cast<size_t>(i)].height != -1 || ++free_count > static_cast<int32_t>(nodes_.size())) return false;
  }
  const int32_t used = leaves == 0 ? 0 : 2 * leaves - 1;
  return used + free_count == static_cast<int32_t>(nodes_.size());
}

}  // namespace frusta
