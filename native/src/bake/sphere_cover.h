// SPDX-License-Identifier: MIT
// Surface-fitted leaf spheres. Greedy cover: take a surface point that no sphere
// reaches within the error budget, put the largest ball inside the solid that
// touches the surface there (the shrinking-ball construction of Ma et al., "3D
// medial axis point approximation using nearest neighbors and the normal field",
// 2012), repeat. Near convex edges such balls vanish, so a ball never gets smaller
// than half the budget: it may then stand out of the surface by at most that.
// Then the interior is filled with inscribed balls until every interior grid point
// lies in a leaf, so a finger that starts deep inside still meets spheres.
#pragma once

#include <functional>
#include <vector>

#include "bake/mesh_queries.h"

namespace frusta {

struct CoverParams {
  double target_error = 0.001;  // metres
  int64_t max_leaves = 100000;
  uint64_t seed = 1;
  // at most this many surface samples (at least 2e4): fewer than the target's density
  // asks for test cheaply whether the budget can fit the target at all, since a cover
  // of sparser samples needs no more leaves; the cover is then not one of the target
  double max_samples = 4e6;
};

struct CoverResult {
  std::vector<Sphere> leaves;
  bool budget_exhausted = false;  // max_leaves reached before the target was met
  bool cancelled = false;         // progress returned false; leaves are incomplete
  size_t surface_samples = 0;
  // the share of the surface samples visited when the budget ran out (1 when it ran out
  // filling the interior): how far short of the target the budget fell
  double reached = 1.0;
  // fewer samples than the target's density asks for (CoverParams::max_samples): leaves
  // that fit the budget are no cover of the target
  bool sparse = false;
};

// progress(fraction 0..1) is called now and then; return false to cancel.
using ProgressFn = std::function<bool(double fraction)>;

CoverResult cover_with_spheres(const TriangleMesh& mesh, const MeshQueries& queries,
                               const CoverParams& params, const ProgressFn& progress);

// The largest ball inside the solid that touches the surface at `point` (outward
// `normal`), no larger than max_radius.
Sphere shrinking_ball(const MeshQueries& queries, const vec3& point, const vec3& normal,
                      double max_radius);

}  // namespace frusta
