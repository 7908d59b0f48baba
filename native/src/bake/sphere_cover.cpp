// SPDX-License-Identifier: MIT
#include "bake/sphere_cover.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include <glm/geometric.hpp>

#include "spheretree/tree_builder.h"

namespace frusta {

namespace {

// Sample points bucketed on a uniform grid, to find those a new ball reaches.
class SampleGrid {
 public:
  SampleGrid(const std::vector<SurfaceSample>& samples, double cell) : cell_(cell) {
    for (uint32_t i = 0; i < samples.size(); ++i) cells_[key(cell_of(samples[i].point))].push_back(i);
  }
  template <class Visit>
  void for_each_near(const vec3& center, double reach, Visit visit) const {
    const glm::i64vec3 lo = cell_of(center - reach), hi = cell_of(center + reach);
    for (int64_t x = lo.x; x <= hi.x; ++x)
      for (int64_t y = lo.y; y <= hi.y; ++y)
        for (int64_t z = lo.z; z <= hi.z; ++z) {
          const auto it = cells_.find(key({x, y, z}));
          if (it == cells_.end()) continue;
          for (uint32_t i : it->second) visit(i);
        }
  }
  glm::i64vec3 cell_of(const vec3& p) const {
    return glm::i64vec3(std::floor(p.x / cell_), std::floor(p.y / cell_), std::floor(p.z / cell_));
  }

 private:
  static uint64_t key(const glm::i64vec3& c) {
    return (static_cast<uint64_t>(c.x) & 0x1fffff) | (static_cast<uint64_t>(c.y) & 0x1fffff) << 21 |
           (static_cast<uint64_t>(c.z) & 0x1fffff) << 42;
  }
  double cell_;
  std::unordered_map<uint64_t, std::vector<uint32_t>> cells_;
};

struct Bounds {
  vec3 lo{INFINITY}, hi{-INFINITY};
  double diagonal() const { return glm::length(hi - lo); }
};

Bounds bounds_of(const TriangleMesh& mesh) {
  Bounds b;
  for (const vec3& v : mesh.vertices) {
    b.lo = glm::min(b.lo, v);
    b.hi = glm::max(b.hi, v);
  }
  return b;
}

}  // namespace

Sphere shrinking_ball(const MeshQueries& queries, const vec3& point, const vec3& normal,
                      double max_radius) {
  double r = max_radius;
  for (int iteration = 0; iteration < 64; ++iteration) {
    // only surface nearer than r can invalidate the ball: search no further
    const MeshQueries::Closest q = queries.closest(point - r * normal, r * (1.0 - 1e-9));
    if (q.distance >= r * (1.0 - 1e-9)) return {point - r * normal, r};  // nothing nearer
    // shrink to the ball tangent at `point` through q: |c - q| = r with c = point - r n;
    // when q lies on the outer side of the tangent plane no such ball exists: halve
    const vec3 d = point - q.point;
    const double along = glm::dot(d, normal);
    const double through = along > 0.0 ? glm::dot(d, d) / (2.0 * along) : 0.0;
    r = through > 0.0 && through < r ? through : 0.5 * r;
  }
  return {point, 0.0};  // no ball fits: the caller's minimum radius takes over
}

CoverResult cover_with_spheres(const TriangleMesh& mesh, const MeshQueries& queries,
                               const CoverParams& params, const ProgressFn& progress) {
  CoverResult result;
  const double e = params.target_error;
  const double area = surface_area(mesh);
  const Bounds box = bounds_of(mesh);
  // samples about e/3 apart; a gap between samples is then at most ~e/3 larger than
  // at them, so they are covered to 0.6 e
  const double spacing = e / 3.0;
  const size_t wanted = static_cast<size_t>(std::clamp(area / (spacing * spacing), 2e4, 4e6));
  const size_t count = std::min(wanted, static_cast<size_t>(std::clamp(params.max_samples, 2e4, 4e6)));
  result.sparse = count < wanted;
  const double cover_error = std::max(0.3 * e, e - 1.2 * std::sqrt(area / static_cast<double>(count)));
  const double min_radius = 0.5 * e;  // the most a ball may stand out at an edge
  // a medial ball may be as large as the object, but near a medial point (a ball's
  // centre) every triangle is equally far and a distance query visits them all;
  // past ~30 e a larger ball barely widens what it covers within e
  const double max_radius = std::min(0.5 * box.diagonal(), 32.0 * e);

  std::vector<SurfaceSample> samples = sample_surface(mesh, count, params.seed);
  result.surface_samples = samples.size();
  const double cell = std::max(4.0 * e, box.diagonal() / 256.0);
  // visit samples in grid order so the cover grows as a front, not at random
  {
    const SampleGrid order_grid(samples, cell);
    std::stable_sort(samples.begin(), samples.end(), [&](const auto& a, const auto& b) {
      const auto ca = order_grid.cell_of(a.point), cb = order_grid.cell_of(b.point);
      return std::tie(ca.x, ca.y, ca.z) < std::tie(cb.x, cb.y, cb.z);
    });
  }
  const SampleGrid grid(samples, cell);
  std::vector<double> gap(samples.size(), INFINITY);

  auto add_ball = [&](const Sphere& ball) {
    result.leaves.push_back(ball);
    grid.for_each_near(ball.center, ball.radius + cover_error, [&](uint32_t j) {
      gap[j] = std::min(gap[j], glm::length(samples[j].point - ball.center) - ball.radius);
    });
  };

  for (size_t i = 0; i < samples.size(); ++i) {
    if (gap[i] <= cover_error) continue;
    if (static_cast<int64_t>(result.leaves.size()) >= params.max_leaves) {
      result.budget_exhausted = true;
      result.reached = static_cast<double>(i) / static_cast<double>(samples.size());
      break;
    }
    Sphere ball = shrinking_ball(queries, samples[i].point, samples[i].normal, max_radius);
    if (ball.radius < min_radius) ball = {samples[i].point - min_radius * samples[i].normal, min_radius};
    add_ball(ball);
    if ((i & 1023) == 0 && progress && !progress(0.8 * static_cast<double>(i) / static_cast<double>(samples.size()))) {
      result.cancelled = true;
      return result;
    }
  }

  // interior: every grid point inside the solid must lie in some leaf
  SphereTree surface;
  if (!result.leaves.empty() && build_sphere_tree(result.leaves, {8}, &surface) != FRUSTA_OK)
    return result;
  const double step = std::max(2.0 * e, box.diagonal() / 48.0);
  std::vector<Sphere> interior;
  for (double x = box.lo.x + 0.5 * step; x < box.hi.x; x += step) {
    if (progress && !progress(0.8 + 0.2 * (x - box.lo.x) / (box.hi.x - box.lo.x))) {
      result.cancelled = true;
      return result;
    }
    for (double y = box.lo.y + 0.5 * step; y < box.hi.y; y += step)
      for (double z = box.lo.z + 0.5 * step; z < box.hi.z; z += step) {
        const vec3 p(x, y, z);
        bool covered = false;
        for (const Sphere& s : interior) covered = covered || glm::length(p - s.center) < s.radius;
        if (covered || distance_to_leaves(surface, p) < 0.0 || !queries.inside(p)) continue;
        const double r = queries.closest(p).distance;
        if (r < min_radius) continue;  // too close to the surface: the surface leaves own it
        if (static_cast<int64_t>(result.leaves.size()) >= params.max_leaves) {
          result.budget_exhausted = true;
          return result;
        }
        interior.push_back({p, r});
        result.leaves.push_back({p, r});
      }
  }
  return result;
}

}  // namespace frusta
