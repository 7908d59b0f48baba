// SPDX-License-Identifier: MIT
// Closest-point and inside/outside queries on a triangle mesh, on Embree 3's BVH.
// Thread-safe for concurrent queries once built.
#pragma once

#include <limits>
#include <memory>

#include "bake/triangle_mesh.h"

namespace frusta {

class MeshQueries {
 public:
  // Builds the BVH; the mesh must have passed check_mesh. Fails only if Embree does.
  static frusta_result create(const TriangleMesh& mesh, std::unique_ptr<MeshQueries>* out);
  ~MeshQueries();
  MeshQueries(const MeshQueries&) = delete;
  MeshQueries& operator=(const MeshQueries&) = delete;

  struct Closest {
    double distance = 0.0;
    vec3 point{0.0};
  };
  // Nearest surface point (unsigned distance). With a finite max_distance only
  // surface within it is searched (much faster near a medial point, where every
  // triangle is almost equally far); none there gives distance = infinity.
  Closest closest(const vec3& point,
                  double max_distance = std::numeric_limits<double>::infinity()) const;

  // Inside the solid the mesh bounds. Rays in five fixed directions each count the
  // winding number (+1 per surface left, -1 per surface entered) and vote inside when
  // it is positive; the majority decides. Exact for closed, consistently wound
  // meshes, overlapping shells included (a point in two shells has winding 2); on
  // an open mesh a ray escaping through a hole is outvoted by the others.
  bool inside(const vec3& point) const;

  // Signed distance: negative inside.
  double signed_distance(const vec3& point) const;

 private:
  MeshQueries() = default;
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace frusta
