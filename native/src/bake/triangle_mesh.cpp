// SPDX-License-Identifier: MIT
#include "bake/triangle_mesh.h"

#include <algorithm>
#include <cmath>
#include <random>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "core/validate.h"

namespace frusta {

namespace {
vec3 corner(const TriangleMesh& m, size_t t, int k) { return m.vertices[m.triangles[t][k]]; }

vec3 area_vector(const TriangleMesh& m, size_t t) {
  return 0.5 * glm::cross(corner(m, t, 1) - corner(m, t, 0), corner(m, t, 2) - corner(m, t, 0));
}
}  // namespace

frusta_result check_mesh(const TriangleMesh& mesh, const char* name) {
  for (size_t i = 0; i < mesh.vertices.size(); ++i) {
    const vec3& v = mesh.vertices[i];
    for (int k = 0; k < 3; ++k) {
      if (!std::isfinite(v[k]))
        return fail(FRUSTA_ERROR_NOT_FINITE, "%s: vertex %zu is not finite", name, i);
      if (std::fabs(v[k]) > kMaxCoordinate)
        return fail(FRUSTA_ERROR_OUT_OF_RANGE, "%s: vertex %zu has coordinate %g m, beyond %g m",
                    name, i, v[k], kMaxCoordinate);
    }
  }
  bool any_area = false;
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k)
      if (mesh.triangles[t][k] >= mesh.vertices.size())
        return fail(FRUSTA_ERROR_OUT_OF_RANGE, "%s: triangle %zu uses vertex %u of %zu", name, t,
                    mesh.triangles[t][k], mesh.vertices.size());
    any_area = any_area || glm::length(area_vector(mesh, t)) > 0.0;
  }
  if (!any_area)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "%s: no triangles with area (%zu triangles)", name,
                mesh.triangles.size());
  return FRUSTA_OK;
}

double surface_area(const TriangleMesh& mesh) {
  double area = 0.0;
  for (size_t t = 0; t < mesh.triangles.size(); ++t) area += glm::length(area_vector(mesh, t));
  return area;
}

std::vector<SurfaceSample> sample_surface(const TriangleMesh& mesh, size_t count, uint64_t seed) {
  std::vector<double> cumulative(mesh.triangles.size());
  double total = 0.0;
  for (size_t t = 0; t < mesh.triangles.size(); ++t) cumulative[t] = total += glm::length(area_vector(mesh, t));
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<SurfaceSample> samples;
  samples.reserve(count);
  for (size_t i = 0; i < count; ++i) {
    const double pick = unit(rng) * total;
    size_t t = static_cast<size_t>(std::upper_bound(cumulative.begin(), cumulative.end(), pick) -
                                   cumulative.begin());
    t = std::min(t, cumulative.size() - 1);
    double a = unit(rng), b = unit(rng);
    if (a + b > 1.0) a = 1.0 - a, b = 1.0 - b;  // fold the square onto the triangle
    const vec3 p0 = corner(mesh, t, 0);
    samples.push_back({p0 + a * (corner(mesh, t, 1) - p0) + b * (corner(mesh, t, 2) - p0),
                       glm::normalize(area_vector(mesh, t))});
  }
  return samples;
}

}  // namespace frusta
