// SPDX-License-Identifier: MIT
// A triangle soup in metres, as the baker takes it from glTF or from a host
// (the Unity editor hands over meshes it already holds).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/base.h"
#include "geometry/types.h"

namespace frusta {

struct TriangleMesh {
  std::vector<vec3> vertices;
  std::vector<std::array<uint32_t, 3>> triangles;  // counter-clockwise seen from outside
};

// Every vertex finite and within kMaxCoordinate, every index in range, and at least
// one triangle with area. `name` prefixes the message (a file, or "mesh").
frusta_result check_mesh(const TriangleMesh& mesh, const char* name);

// Area-weighted uniform random points on the surface with their outward normals.
struct SurfaceSample {
  vec3 point;
  vec3 normal;
};
std::vector<SurfaceSample> sample_surface(const TriangleMesh& mesh, size_t count, uint64_t seed);

double surface_area(const TriangleMesh& mesh);

}  // namespace frusta
