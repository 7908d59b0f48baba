// SPDX-License-Identifier: MIT
// Builds the hierarchy over a given set of leaf spheres: top-down median splits of
// the leaf centres, each node bounding exactly the leaves beneath it.
#pragma once

#include <vector>

#include "core/base.h"
#include "spheretree/sphere_tree.h"

namespace frusta {

struct TreeBuildOptions {
  int32_t branching = 4;  // children per inner node, 2..kMaxBranching
};

// Leaves keep their numbering. Fails (with the thread's error set) on a non-finite
// or negative leaf, too many leaves, or a bad branching factor.
frusta_result build_sphere_tree(const std::vector<Sphere>& leaves, const TreeBuildOptions& options,
                                SphereTree* out);

// The smallest float sphere (centre rounded, radius rounded up) that contains
// every given double sphere; shared with the loader's containment check.
TreeNode bounding_node(const Sphere* const* spheres, size_t count);

}  // namespace frusta
