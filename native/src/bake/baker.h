// SPDX-License-Identifier: MIT
// Mesh in, sphere tree out, with its approximation error measured independently
// of the construction (fresh samples, Embree distances and inside tests).
#pragma once

#include "bake/bake_params.h"
#include "bake/sphere_cover.h"
#include "spheretree/tree_file.h"
#include "spheretree/tree_limits.h"

namespace frusta {

struct BakeError {
  double uncovered = 0.0;   // largest distance from a surface point to the leaves
  double protruding = 0.0;  // largest distance from a leaf surface point out of the mesh
  int64_t samples = 0;
  bool cancelled = false;   // progress said stop: the figures are partial
};

// progress (may be empty) as sphere_cover.h's, over the measurement.
BakeError measure_bake_error(const MeshQueries& queries, const TriangleMesh& mesh,
                             const SphereTree& tree, int64_t samples, uint64_t seed,
                             const ProgressFn& progress = {});

// The whole bake; params are checked (check_bake_params) before anything else.
// *target_met says whether both figures came out at or under the
// target (they may not when max_leaves runs out first); the tree is valid either way.
frusta_result bake_sphere_tree(const TriangleMesh& mesh, const BakeParams& params,
                               const ProgressFn& progress, TreeFile* out, bool* target_met);

}  // namespace frusta
