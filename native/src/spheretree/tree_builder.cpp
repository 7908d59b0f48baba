// SPDX-License-Identifier: MIT
#include "spheretree/tree_builder.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "spheretree/node_error.h"
#include "spheretree/tree_limits.h"

namespace frusta {

namespace {

struct Builder {
  const std::vector<Sphere>& leaves;
  int32_t branching;
  SphereTree& tree;
  std::vector<int32_t> order;  // leaf numbers, permuted as ranges are split
  std::vector<const Sphere*> scratch;

  void bound(int32_t node, size_t begin, size_t end) {
    scratch.clear();
    for (size_t i = begin; i < end; ++i) scratch.push_back(&leaves[static_cast<size_t>(order[i])]);
    const TreeNode b = bounding_node(scratch.data(), scratch.size());
    TreeNode& n = tree.nodes[static_cast<size_t>(node)];
    std::copy(b.center, b.center + 3, n.center);
    n.radius = b.radius;
  }

  // cut [begin, end) into `parts` groups of equal size (within one leaf): split at the
  // proportional rank along the centres' widest axis, then recurse into each side
  void partition(size_t begin, size_t end, int32_t parts,
                 std::vector<std::pair<size_t, size_t>>& groups) {
    const size_t n = end - begin;
    if (parts == 1 || n < 2) {
      groups.emplace_back(begin, end);
      return;
    }
    const int32_t left_parts = parts / 2;
    const size_t cut = begin + std::max<size_t>(1, n * static_cast<size_t>(left_parts) /
                                                       static_cast<size_t>(parts));
    vec3 lo(INFINITY), hi(-INFINITY);
    for (size_t i = begin; i < end; ++i) {
      lo = glm::min(lo, leaves[static_cast<size_t>(order[i])].center);
      hi = glm::max(hi, leaves[static_cast<size_t>(order[i])].center);
    }
    const vec3 extent = hi - lo;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
    auto at = [&](size_t i) { return order.begin() + static_cast<std::ptrdiff_t>(i); };
    std::nth_element(at(begin), at(cut), at(end), [&](int32_t a, int32_t b) {
      const double ca = leaves[static_cast<size_t>(a)].center[axis];
      const double cb = leaves[static_cast<size_t>(b)].center[axis];
      return ca < cb || (ca == cb && a < b);  // ties by number: deterministic
    });
    partition(begin, cut, left_parts, groups);
    partition(cut, end, parts - left_parts, groups);
  }

  void build(int32_t node, size_t begin, size_t end, int32_t level) {
    tree.depth = std::max(tree.depth, level);
    bound(node, begin, end);
    TreeNode& n = tree.nodes[static_cast<size_t>(node)];
    if (end - begin == 1) {
      n.first = order[begin];
      n.count = 0;
      return;
    }
    std::vector<std::pair<size_t, size_t>> groups;
    partition(begin, end, std::min<int32_t>(branching, static_cast<int32_t>(end - begin)), groups);
    const int32_t first = static_cast<int32_t>(tree.nodes.size());
    n.first = first;
    n.count = static_cast<int32_t>(groups.size());
    tree.nodes.resize(tree.nodes.size() + groups.size());
    for (size_t g = 0; g < groups.size(); ++g)
      build(first + static_cast<int32_t>(g), groups[g].first, groups[g].second, level + 1);
  }
};

}  // namespace

TreeNode bounding_node(const Sphere* const* spheres, size_t count) {
  // centre of the spheres' bounding box, then the radius that reaches every sphere
  vec3 lo(INFINITY), hi(-INFINITY);
  for (size_t i = 0; i < count; ++i) {
    lo = glm::min(lo, spheres[i]->center - spheres[i]->radius);
    hi = glm::max(hi, spheres[i]->center + spheres[i]->radius);
  }
  TreeNode n{};
  const vec3 mid = 0.5 * (lo + hi);
  for (int k = 0; k < 3; ++k) n.center[k] = static_cast<float>(mid[k]);
  const vec3 c(n.center[0], n.center[1], n.center[2]);  // the stored centre, after rounding
  double radius = 0.0;
  for (size_t i = 0; i < count; ++i)
    radius = std::max(radius, glm::length(spheres[i]->center - c) + spheres[i]->radius);
  // round up by a float ulp beyond the double's own rounding, so containment holds
  float r = static_cast<float>(radius);
  while (static_cast<double>(r) < radius * (1.0 + 1e-12)) r = std::nextafter(r, INFINITY);
  n.radius = r;
  return n;
}

frusta_result build_sphere_tree(const std::vector<Sphere>& leaves, const TreeBuildOptions& options,
                                SphereTree* out) {
  if (options.branching < 2 || options.branching > kMaxBranching)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "branching is %d, must be 2..%d", options.branching,
                kMaxBranching);
  if (leaves.empty()) return fail(FRUSTA_ERROR_OUT_OF_RANGE, "a sphere tree needs at least one leaf");
  if (static_cast<int64_t>(leaves.size()) > kMaxLeaves)
    return fail(FRUSTA_ERROR_CAPACITY, "%zu leaves, more than the limit of %lld", leaves.size(),
                static_cast<long long>(kMaxLeaves));
  for (size_t i = 0; i < leaves.size(); ++i) {
    const Sphere& s = leaves[i];
    const bool finite = std::isfinite(s.center.x) && std::isfinite(s.center.y) &&
                        std::isfinite(s.center.z) && std::isfinite(s.radius);
    if (!finite) return fail(FRUSTA_ERROR_NOT_FINITE, "leaf %zu is not finite", i);
    if (s.radius < 0.0) return fail(FRUSTA_ERROR_OUT_OF_RANGE, "leaf %zu has radius %g", i, s.radius);
  }
  SphereTree tree;
  tree.leaves = leaves;
  tree.branching = options.branching;
  tree.nodes.reserve(2 * leaves.size());
  tree.nodes.resize(1);
  Builder builder{tree.leaves, options.branching, tree, std::vector<int32_t>(leaves.size()), {}};
  std::iota(builder.order.begin(), builder.order.end(), 0);
  builder.build(0, 0, leaves.size(), 0);
  compute_node_errors(tree);
  *out = std::move(tree);
  return FRUSTA_OK;
}

}  // namespace frusta
